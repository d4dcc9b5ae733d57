// The page in a student's hands (tests/web/run.sh runs it after page_test.mjs): a tablet's
// fingers through the browser's own touch events (CDP Input.dispatchTouchEvent in a context
// with touch), a laptop's mouse and keys, a phone's narrow screen. It checks, as a student
// would meet it:
//   1. a finger dragged up the panel scrolls it (the Data section comes into reach) and presses
//      nothing; a finger still taps a checkbox, drags a slider across and opens a section;
//   2. no hover outlives a finger: no tooltip stands after a tap, no "new ball" outline after a
//      pinch; with a mouse, a tooltip waits for a real hover and never shows while a field is
//      typed in;
//   3. the help (H) and the tooltips name no key the browser keeps (Ctrl+N, Ctrl+T, Ctrl+plus,
//      minus, 0);
//   4. nothing of the page's own lies over the canvas: About is the panel's button;
//   5. a phone (390x844): the panel opens over the box as a sheet at the phone's full width, the
//      readouts above the box are whole lines, and the box is a usable size;
//   6. after Save and Export the panel names the file and says it is a download, never the
//      page's own folder.
// Screenshots are written to PSB_WEB_SHOTS (classroom-*.png) for a person to look at.
import fs from "fs";
import path from "path";

import { chromium, launchOptions } from "./chromium.mjs";

const url = process.env.PSB_WEB_URL;
const shots = process.env.PSB_WEB_SHOTS;
fs.mkdirSync(shots, { recursive: true });

let failures = 0;
function check(ok, what) {
  console.log(`${ok ? "ok  " : "FAIL"} ${what}`);
  if (!ok) failures++;
}

const browser = await chromium.launch(launchOptions());
const errors = [];

/// A page of the program in a fresh context: `viewport`, touch or not.
async function open(viewport, options = {}) {
  const context = await browser.newContext({
    viewport, hasTouch: true, acceptDownloads: true, ...options,
  });
  const page = await context.newPage();
  page.on("pageerror", (e) => errors.push(e.message));
  const cdp = await context.newCDPSession(page);
  const p = {
    page, context,
    log: () => page.evaluate(() => window.psbLog.slice()),
    title: () => page.title(),
    async shot(name) {
      return (await page.screenshot({ path: path.join(shots, `classroom-${name}.png`) }))
        .toString("base64");
    },
    async waitFor(what, test, seconds = 10) {
      for (let t = 0; t < seconds * 10; t++) {
        if (await test()) return true;
        await page.waitForTimeout(100);
      }
      console.log(`  (timed out waiting for ${what})`);
      return false;
    },
    /// The panel's control `name` from --log-controls: its centre, CSS pixels.
    async control(name) {
      const lines = (await p.log()).filter((l) => l.startsWith(`[I] Control ${name} at `));
      if (lines.length === 0) return null;
      const m = lines[lines.length - 1].match(/ at (-?\d+) (-?\d+)$/);
      return { x: +m[1], y: +m[2] };
    },
    /// What the status line `name` says, from --log-controls.
    async says(name) {
      const lines = (await p.log()).filter((l) => l.startsWith(`[I] Control ${name} says `));
      return lines.length ? lines[lines.length - 1].slice(`[I] Control ${name} says `.length) : null;
    },
    async lastTooltip() {
      const lines = (await p.log()).filter((l) => l.startsWith("[I] Tooltip "));
      return lines.length ? lines[lines.length - 1].slice("[I] Tooltip ".length) : null;
    },
    touch: (type, points) => cdp.send("Input.dispatchTouchEvent", {
      type, touchPoints: points.map(([x, y], id) => ({ x, y, id })) }),
    async tap(at) {
      await p.touch("touchStart", [[at.x, at.y]]);
      await page.waitForTimeout(80);
      await p.touch("touchEnd", []);
      await page.waitForTimeout(300);
    },
    async drag(from, to, steps = 12) {
      await p.touch("touchStart", [[from.x, from.y]]);
      for (let k = 1; k <= steps; k++) {
        await p.touch("touchMove", [[from.x + (to.x - from.x) * k / steps,
                                     from.y + (to.y - from.y) * k / steps]]);
        await page.waitForTimeout(16);
      }
      await p.touch("touchEnd", []);
    },
    /// Pixels of rect that differ between two screenshots (base64 PNGs).
    changed: (a, b, rect) => page.evaluate(async ([a, b, rect]) => {
      const load = async (data) => {
        const img = new Image();
        img.src = "data:image/png;base64," + data;
        await img.decode();
        const c = document.createElement("canvas");
        c.width = img.width;
        c.height = img.height;
        const g = c.getContext("2d");
        g.drawImage(img, 0, 0);
        return g.getImageData(0, 0, c.width, c.height);
      };
      const A = await load(a), B = await load(b);
      let n = 0;
      for (let y = Math.max(0, rect.y0); y < Math.min(A.height, rect.y1); y++)
        for (let x = Math.max(0, rect.x0); x < Math.min(A.width, rect.x1); x++) {
          const i = (y * A.width + x) * 4;
          const d = Math.abs(A.data[i] - B.data[i]) + Math.abs(A.data[i + 1] - B.data[i + 1]) +
                    Math.abs(A.data[i + 2] - B.data[i + 2]);
          if (d > 30) n++;
        }
      return n;
    }, [a, b, rect]),
    /// The page's own elements that are shown over the canvas.
    overCanvas: () => page.evaluate(() => [...document.body.children]
      .filter((e) => e.id !== "canvas" && !["SCRIPT", "INPUT", "A"].includes(e.tagName))
      .filter((e) => {
        const r = e.getBoundingClientRect(), s = getComputedStyle(e);
        return s.display !== "none" && s.visibility !== "hidden" && r.width > 0 && r.height > 0;
      })
      .map((e) => e.id || e.tagName)),
  };
  return p;
}

async function started(p, query) {
  await p.page.goto(url + query);
  return p.waitFor("the program", async () => /particles/.test(await p.title()), 60);
}

// ---------------------------------------------------------------------------------------------
// A tablet: 1024x768, fingers only, the Billiards preset.
{
  const p = await open({ width: 1024, height: 768 });
  check(await started(p, "?log-controls&seed=7"), "the page starts on a tablet");
  await p.page.keyboard.press("3");
  await p.waitFor("the Billiards preset", async () => /Billiards/i.test(await p.title()));
  check(/Billiards/i.test(await p.title()), `Billiards opens: ${await p.title()}`);
  await p.page.waitForTimeout(500);

  // 4. Nothing of the page's own over the canvas.
  const over = await p.overCanvas();
  check(over.length === 0, `nothing of the page lies over the canvas: ${JSON.stringify(over)}`);

  // 1. A finger still reaches the controls: a checkbox tapped, a slider dragged across.
  const labels = await p.control("Labels");
  if (labels) await p.tap(labels);
  await p.waitFor("labels", async () => (await p.log()).some((l) => l.includes("Labels on")), 3);
  check((await p.log()).some((l) => l.includes("Labels on")), "a tap ticks a checkbox (Labels)");
  const speed = await p.control("Speed");
  const speedsBefore = (await p.log()).filter((l) => l.includes("Time speed")).length;
  if (speed) await p.drag(speed, { x: speed.x + 60, y: speed.y + 2 }, 8);
  await p.waitFor("the speed", async () =>
    (await p.log()).filter((l) => l.includes("Time speed")).length > speedsBefore, 3);
  check((await p.log()).filter((l) => l.includes("Time speed")).length > speedsBefore,
        "a finger dragged across a slider moves it: " +
        ((await p.log()).filter((l) => l.includes("Time speed")).pop() || "nothing"));

  // 2. No tooltip stands after a tap: the disabled "Fwd >" (a tap changes nothing there).
  const fwd = await p.control("Step forward");
  const beforeTap = await p.shot("1-before-tap");
  if (fwd) await p.tap(fwd);
  await p.page.waitForTimeout(1200);
  const afterTap = await p.shot("2-after-tap");
  const tipArea = fwd && { x0: fwd.x + 14, y0: fwd.y + 12, x1: fwd.x + 420, y1: fwd.y + 90 };
  const tipPixels = fwd ? await p.changed(beforeTap, afterTap, tipArea) : -1;
  check(tipPixels >= 0 && tipPixels < 40,
        `no tooltip stays after a tap: ${tipPixels} pixels changed beside the finger`);
  const tip = await p.lastTooltip();
  check(tip === null || tip === "none", `the program shows no tooltip after the tap: ${tip}`);

  // 1. A finger dragged up the panel scrolls it, and presses nothing.
  const data0 = await p.control("section Data");
  const title0 = await p.title();
  await p.drag({ x: 150, y: 650 }, { x: 150, y: 250 }, 14);
  await p.page.waitForTimeout(1000);  // coasting, then still
  const data1 = await p.control("section Data");
  const moved = data0 && data1 ? data0.y - data1.y : 0;
  await p.shot("3-scrolled");
  check(moved >= 300, `a finger dragged 400 px up the panel scrolls it: the Data section ` +
        `${data0 && data0.y} -> ${data1 && data1.y}`);
  check((await p.title()) === title0, `the scroll pressed nothing: ${await p.title()}`);
  if (data1 && data1.y > 0 && data1.y < 768) {
    await p.tap(data1);
    await p.waitFor("the Data section", async () => (await p.control("Export values")) !== null, 3);
  }
  check((await p.control("Export values")) !== null,
        "the Data section, below the fold before, opens with a tap");
  await p.shot("4-data-open");

  // 2. After a pinch on the box, no "new ball" outline stays where a finger was.
  const cx = 650, cy = 420;
  await p.touch("touchStart", [[cx - 100, cy], [cx + 100, cy]]);
  for (let k = 1; k <= 9; k++) {
    await p.touch("touchMove", [[cx - 100 + 5 * k, cy], [cx + 100 - 5 * k, cy]]);
    await p.page.waitForTimeout(16);
  }
  await p.touch("touchEnd", []);
  await p.page.waitForTimeout(400);
  const afterPinch = await p.shot("5-after-pinch");
  await p.page.mouse.move(60, 10);  // a mouse now, over the panel: no outline in the box
  await p.page.waitForTimeout(400);
  const mouseAway = await p.shot("6-mouse-on-panel");
  const outline = await p.changed(afterPinch, mouseAway,
                                  { x0: cx - 140, y0: cy - 90, x1: cx + 40, y1: cy + 90 });
  check(outline < 20, `no outline stays where a pinching finger lifted: ${outline} pixels`);
  await p.context.close();
}

// ---------------------------------------------------------------------------------------------
// A laptop: the mouse and the keys, 1200x800.
{
  const p = await open({ width: 1200, height: 800 }, { hasTouch: false });
  check(await started(p, "?log-controls&seed=7&paused"), "the page starts on a laptop");
  await p.page.waitForTimeout(500);

  // 3. The help and the tooltips name no key the browser keeps.
  const kept = /Ctrl\+N\b|Ctrl\+T\b|Ctrl\+plus|Ctrl\+minus|Ctrl\+0/;
  const help = (await p.log()).filter((l) => l.startsWith("    "));
  check(help.length > 20 && !help.some((l) => kept.test(l)),
        "the help lists no key the browser keeps: " +
        (help.filter((l) => kept.test(l)).map((l) => l.trim()).join("; ") || `${help.length} lines`));
  check(help.some((l) => /Show: UI scale/.test(l)) && help.some((l) => /Show: Light/.test(l)) &&
        help.some((l) => /New scene/.test(l)),
        "the help names the panel's control for each of those actions");
  const tips = {};
  const hover = async (name) => {
    const c = await p.control(name);
    if (!c) return;
    await p.page.mouse.move(c.x, c.y);
    await p.waitFor(`the tooltip of ${name}`, async () =>
      !["none", null].includes(await p.lastTooltip()), 3);
    tips[name] = await p.lastTooltip();
    await p.page.mouse.move(60, 10);
    await p.page.waitForTimeout(200);
  };
  for (const name of ["theme Light", "UI scale", "UI scale auto"]) await hover(name);
  const scene = await p.control("section Scene");
  await p.page.mouse.click(scene.x, scene.y);
  await p.page.waitForTimeout(400);
  await hover("New scene");
  const shown = Object.values(tips).filter((t) => t && t !== "none");
  check(shown.length === 4 && !shown.some((t) => kept.test(t)),
        `the tooltips of New scene, Light, UI scale and Auto name no such key: ` +
        JSON.stringify(tips));

  // 2. A tooltip waits for a real hover, and never covers a field being typed in.
  const title = await p.control("title");
  await p.page.mouse.move(60, 10);
  await p.page.waitForTimeout(300);
  const before = await p.shot("7-before-typing");
  await p.page.mouse.click(title.x, title.y);
  await p.page.waitForTimeout(300);  // the field takes text from the next frame on
  await p.page.keyboard.type("Momentum lesson", { delay: 40 });
  await p.page.waitForTimeout(1200);
  const typing = await p.shot("8-typing");
  // Below the field and to the right of the pointer, where ImGui puts a tooltip.
  const covered = await p.changed(before, typing,
                                  { x0: title.x + 14, y0: title.y + 14, x1: title.x + 420, y1: title.y + 100 });
  check(covered < 40, `no tooltip over the fields while typing: ${covered} pixels changed`);
  const typingTip = await p.lastTooltip();
  check(typingTip === null || typingTip === "none", `no tooltip shown while typing: ${typingTip}`);
  await p.page.keyboard.down("Enter");
  await p.page.waitForTimeout(100);
  await p.page.keyboard.up("Enter");
  await p.page.waitForTimeout(300);

  // 6. After Save, the panel names the file and says it went to the downloads.
  const download = p.page.waitForEvent("download", { timeout: 15000 });
  const save = await p.control("Save");
  await p.page.mouse.click(save.x, save.y);
  await p.page.waitForTimeout(400);
  await p.page.keyboard.down("Enter");
  await p.page.waitForTimeout(100);
  await p.page.keyboard.up("Enter");
  let name = null;
  try {
    name = (await download).suggestedFilename();
  } catch (e) {
    console.log("  " + e.message.split("\n")[0]);
  }
  await p.waitFor("the saved line", async () => (await p.says("saved")) !== null, 5);
  const file = await p.says("file"), saved = await p.says("saved");
  await p.page.mouse.move(60, 10);
  await p.page.waitForTimeout(300);
  await p.shot("9-saved");
  check(name && file === `File: ${name}`, `the Scene section names the file: ${file}`);
  check(name && saved && saved.startsWith(`Saved as ${name}`) && /your downloads/.test(saved) &&
        !/this computer|Downloads folder/.test(saved) &&
        !/\/files/.test(saved), `it says where the file went: ${saved}`);
  // The Scene section closed and the panel wheeled down: the Data section in view.
  const sceneHeader = await p.control("section Scene");
  await p.page.mouse.click(sceneHeader.x, sceneHeader.y);
  await p.page.waitForTimeout(300);
  for (let k = 0; k < 10 && (await p.control("section Data")).y > 700; k++) {
    await p.page.mouse.move(150, 400);
    await p.page.mouse.wheel(0, 200);
    await p.page.waitForTimeout(200);
  }
  const data = await p.control("section Data");
  await p.page.mouse.click(data.x, data.y);
  await p.waitFor("the Data section", async () => (await p.control("Export values")) !== null, 3);
  const exportDownload = p.page.waitForEvent("download", { timeout: 15000 });
  const exp = await p.control("Export values");
  if (exp) await p.page.mouse.click(exp.x, exp.y);
  try {
    await exportDownload;
  } catch (e) {
    console.log("  " + e.message.split("\n")[0]);
  }
  await p.waitFor("the exported line", async () => (await p.says("exported")) !== null, 5);
  const exported = await p.says("exported");
  check(exported && /^Exported values\.csv/.test(exported) && /your downloads/.test(exported) &&
        !/this computer|Downloads folder/.test(exported) &&
        !/\/files/.test(exported), `Export says where the table went: ${exported}`);

  // 4. About is the panel's, and opens the page's notes.
  await p.page.mouse.move(150, 400);
  for (let k = 0; k < 12; k++) {  // back to the panel's top line (a wheel event is one notch)
    await p.page.mouse.wheel(0, -200);
    await p.page.waitForTimeout(100);
  }
  await p.page.waitForTimeout(400);
  const about = await p.control("About");
  if (about) await p.page.mouse.click(about.x, about.y);
  await p.page.waitForTimeout(300);
  const helpShown = await p.page.evaluate(
    () => getComputedStyle(document.getElementById("help")).display !== "none");
  await p.shot("10-about");
  check(about !== null && helpShown, "the panel's About button opens the page's notes");
  if (helpShown) await p.page.click("#help-close");
  await p.context.close();
}

// ---------------------------------------------------------------------------------------------
// A phone: 390x844, three device pixels to a CSS pixel, fingers only.
{
  const p = await open({ width: 390, height: 844 }, { deviceScaleFactor: 3, isMobile: true });
  check(await started(p, "?log-controls&seed=7"), "the page starts on a phone");
  await p.page.keyboard.press("2");  // Newton's cradle
  await p.page.waitForTimeout(800);
  await p.shot("11-phone");
  const over = await p.overCanvas();
  check(over.length === 0, `nothing of the page lies over a phone's canvas: ${JSON.stringify(over)}`);
  const strip = await p.control("open panel");
  if (strip) await p.tap(strip);
  await p.waitFor("the panel", async () => (await p.control("fold panel")) !== null, 3);
  await p.page.waitForTimeout(500);
  await p.shot("12-phone-panel");
  const fold = await p.control("fold panel");
  check(fold !== null && fold.x > 300,
        `the panel opens as a sheet as wide as the phone: its fold button at x ${fold && fold.x}`);
  // The sheet scrolls under a finger, as on the tablet.
  const readouts0 = await p.control("section Readouts");
  await p.drag({ x: 200, y: 700 }, { x: 200, y: 300 }, 14);
  await p.page.waitForTimeout(1000);
  const readouts1 = await p.control("section Readouts");
  await p.shot("13-phone-panel-scrolled");
  // The sheet's content is about 270 px longer than the phone here: scrolled to its end.
  check(readouts0 && readouts1 && readouts0.y - readouts1.y >= 200,
        `a finger scrolls the phone's panel: ${readouts0 && readouts0.y} -> ${readouts1 && readouts1.y}`);
  if (fold) await p.tap(await p.control("fold panel"));
  await p.page.waitForTimeout(500);
  await p.shot("14-phone-folded");
  await p.context.close();
}

check(errors.length === 0, "no script errors" + (errors.length ? ": " + errors.join("; ") : ""));
await browser.close();
console.log(failures === 0 ? "classroom: all checks passed" : `classroom: ${failures} check(s) failed`);
process.exit(failures === 0 ? 0 : 1);
