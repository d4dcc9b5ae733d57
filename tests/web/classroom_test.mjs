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
//      page's own folder, in words a phone's owner reads too (your downloads);
//   7. a second trial (the tablet's fingers, then the phone's): the on-screen keyboard's text
//      reaches a field, Copy reaches the browser's clipboard, a finger's fling launches as a
//      mouse's, a tap or a scroll that starts on a slider leaves it, the UI scale keeps the panel
//      open, hints name buttons (a peg a finger placed, moved or deleted: the panel's Undo,
//      which brings it back), two fingers on the phone's sheet act on nothing under it.
// Screenshots are written to PSB_WEB_SHOTS (classroom-*.png) for a person to look at.
import fs from "fs";
import path from "path";

import { chromium, launchOptions } from "./chromium.mjs";
import { fingerPage } from "./fingers.mjs";

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
  const p = await fingerPage(browser, {
    viewport, options: { acceptDownloads: true, ...options }, shots, prefix: "classroom", errors,
  });
  const page = p.page;
  Object.assign(p, {
    /// What the status line `name` says, from --log-controls.
    async says(name) {
      const lines = (await p.log()).filter((l) => l.startsWith(`[I] Control ${name} says `));
      return lines.length ? lines[lines.length - 1].slice(`[I] Control ${name} says `.length) : null;
    },
    async lastTooltip() {
      const lines = (await p.log()).filter((l) => l.startsWith("[I] Tooltip "));
      return lines.length ? lines[lines.length - 1].slice("[I] Tooltip ".length) : null;
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
  });
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

  /// The panel's control `name`, scrolled into reach by a finger dragged along the panel (on a
  /// touch screen its targets are a finger's size: Show's boxes are below a tablet's fold).
  const reach = async (name) => {
    for (let k = 0; k < 6; k++) {
      const c = await p.control(name);
      if (!c || (c.y >= 60 && c.y <= 720)) return c;
      const by = Math.max(-300, Math.min(300, c.y - 380));
      await p.drag({ x: 150, y: 400 + by / 2 }, { x: 150, y: 400 - by / 2 }, 10);
      await p.page.waitForTimeout(1000);
    }
    return p.control(name);
  };

  // 1. A finger still reaches the controls: a checkbox tapped, a slider dragged across.
  const labels = await reach("Labels");
  if (labels) await p.tap(labels);
  await p.waitFor("labels", async () => (await p.log()).some((l) => l.includes("Labels on")), 3);
  check((await p.log()).some((l) => l.includes("Labels on")), "a tap ticks a checkbox (Labels)");
  const speed = await reach("Speed");
  const speedsBefore = (await p.log()).filter((l) => l.includes("Time speed")).length;
  if (speed) await p.drag(speed, { x: speed.x + 60, y: speed.y + 2 }, 8);
  await p.waitFor("the speed", async () =>
    (await p.log()).filter((l) => l.includes("Time speed")).length > speedsBefore, 3);
  check((await p.log()).filter((l) => l.includes("Time speed")).length > speedsBefore,
        "a finger dragged across a slider moves it: " +
        ((await p.log()).filter((l) => l.includes("Time speed")).pop() || "nothing"));

  // 2. No tooltip stands after a tap: the disabled "Fwd >" (a tap changes nothing there).
  const fwd = await reach("Step forward");
  await p.page.waitForTimeout(300);
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
  // On a touch screen the panel's targets are a finger's size: the Data section is further
  // down, and more drags bring it up.
  let data2 = data1;
  for (let k = 0; k < 6 && data2 && data2.y > 700; k++) {
    await p.drag({ x: 150, y: 650 }, { x: 150, y: 250 }, 14);
    await p.page.waitForTimeout(1000);
    data2 = await p.control("section Data");
  }
  if (data2 && data2.y > 0 && data2.y < 768) {
    await p.tap(data2);
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

// ---------------------------------------------------------------------------------------------
// The class's second trial, on a tablet's fingers (1024x768, paused): typing with the on-screen
// keyboard, Copy, a fling, a tap and a scroll on a slider, the UI scale, the hints.
{
  const p = await open({ width: 1024, height: 768 });
  await p.context.grantPermissions(["clipboard-read", "clipboard-write"], { origin: url });
  check(await started(p, "?log-controls&seed=7&paused"), "the page starts on a tablet (again)");
  await p.page.waitForTimeout(500);
  const lines = async (re) => (await p.log()).filter((l) => re.test(l));
  const count = async (re) => (await lines(re)).length;
  /// The panel's control `name`, scrolled into reach by a finger dragged along the panel.
  const reach = async (name) => {
    for (let k = 0; k < 6; k++) {
      const c = await p.control(name);
      if (!c || (c.y >= 40 && c.y <= 720)) return c;
      const by = Math.max(-300, Math.min(300, c.y - 380));
      await p.drag({ x: 150, y: 400 + by / 2 }, { x: 150, y: 400 - by / 2 }, 10);
      await p.page.waitForTimeout(1000);
    }
    return p.control(name);
  };

  const scene = await p.control("section Scene");
  await p.tap(scene);
  await p.waitFor("the Scene section", async () => (await p.control("title")) !== null, 3);

  // 1. A field that takes text brings the on-screen keyboard up (the page's typing field has
  //    the focus) and what that keyboard types (the browser's insertText, as a touch
  //    keyboard's, no key events) reaches it; its Enter keeps it.
  // (Below the presets, rows of the panel on a touch screen: scrolled to by a finger.)
  const title = await reach("title");
  if (title) await p.tap(title);
  await p.waitFor("the typing field", async () =>
    (await p.page.evaluate(() => document.activeElement && document.activeElement.id)) === "typing", 3);
  const focused = await p.page.evaluate(() => document.activeElement && document.activeElement.id);
  check(focused === "typing",
        `a tap on the title field focuses the page's typing field (the keyboard comes up): ${focused}`);
  await p.shot("15-typing-tablet");
  await p.page.keyboard.insertText("Momentum lesson");
  await p.page.waitForTimeout(300);
  await p.page.keyboard.press("Enter");
  await p.waitFor("the title", async () => /Momentum lesson/.test(await p.title()), 3);
  check(/Momentum lesson/.test(await p.title()),
        `what the on-screen keyboard typed reaches the field: the title reads "${await p.title()}"`);
  await p.page.waitForTimeout(300);
  const after = await p.page.evaluate(() => document.activeElement && document.activeElement.id);
  check(after !== "typing", `the keyboard goes away once the field is done: focus on ${after}`);

  // 4. A tap on a slider leaves its value; a finger that starts on it and goes up scrolls the
  //    panel and leaves it too; a drag along it changes it.
  // The Scene section folded again: its header reached first (the title's scroll moved it).
  const sceneAgain = await reach("section Scene");
  if (sceneAgain) await p.tap(sceneAgain);
  await p.page.waitForTimeout(300);
  const speed = await reach("Speed");
  const speeds0 = await count(/Time speed/);
  if (speed) await p.tap({ x: speed.x + 70, y: speed.y });
  await p.page.waitForTimeout(500);
  check((await count(/Time speed/)) === speeds0,
        "a tap on a slider does not set its value: " + ((await lines(/Time speed/)).pop() || "unchanged"));
  const probe0 = await p.control("section Data");
  if (speed) {
    await p.touch("touchStart", [[speed.x + 70, speed.y]]);
    await p.page.waitForTimeout(500);  // a finger that rests before it moves
    for (let k = 1; k <= 12; k++) {
      await p.touch("touchMove", [[speed.x + 70 + k, speed.y - 25 * k]]);
      await p.page.waitForTimeout(16);
    }
    await p.touch("touchEnd", []);
  }
  await p.page.waitForTimeout(1000);
  const probe1 = await p.control("section Data");
  check((await count(/Time speed/)) === speeds0,
        "a finger that starts on a slider and goes up leaves its value: " +
        ((await lines(/Time speed/)).pop() || "unchanged"));
  check(probe0 && probe1 && probe0.y - probe1.y > 100,
        `... and scrolls the panel: the Data section ${probe0 && probe0.y} -> ${probe1 && probe1.y}`);
  await p.shot("16-slider-scrolled");

  // 2. Copy: the browser's clipboard holds the table, and the panel says so only then.
  const data = await reach("section Data");
  if (data) await p.tap(data);
  await p.waitFor("the Data section", async () => (await p.control("Copy values")) !== null, 3);
  const copy = await reach("Copy values");
  if (copy) await p.tap(copy);
  await p.waitFor("the copy", async () => (await count(/Copied|Could not copy/)) > 0, 5);
  const clip = await p.page.evaluate(() => navigator.clipboard.readText().catch((e) => "error: " + e));
  const copied = (await lines(/Copied|Could not copy/)).pop() || "nothing said";
  check(/^x_m\t|\tx_m\t/.test(clip.split("\n")[0]) && clip.split("\n").length > 3,
        `Copy puts the values on the browser's clipboard, tab-separated: ${JSON.stringify(clip.slice(0, 60))}`);
  check(/Copied \d+ rows of values/.test(copied), `and says so: ${copied}`);
  await p.shot("17-copied");

  // 3. A finger's quick fling launches as the mouse's fling of the same path. A particle at
  //    rest first (a finger held still on empty space), then the fling from it. Both hands'
  //    events carry the times of one schedule (the browser's own input times, CDP's
  //    `timestamp`): a move every 16 ms, the lift 60 ms after the last. Each is handed over in
  //    a frame of its own (no two moves merged into one); how late the page's handlers run
  //    after those times (this machine's load, the frames) is left to the browser.
  const at = { x: 760, y: 360 };
  const frame = () => p.page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r())));
  const fling = async (hand, path, pause) => {
    const t0 = Date.now() / 1000;
    await hand.down(path[0], t0);
    await p.page.waitForTimeout(pause);
    let t = t0 + pause / 1000;
    for (const q of path.slice(1)) {
      await hand.move(q, t);
      await frame();
      t += 0.016;
    }
    await hand.up(path[path.length - 1], t - 0.016 + 0.06);
    await p.page.waitForTimeout(400);
  };
  const touchAt = (type, q, timestamp) => p.cdp.send("Input.dispatchTouchEvent", {
    type, timestamp, touchPoints: q ? [{ x: q.x, y: q.y, id: 0 }] : [] });
  const finger = {
    down: (q, t) => touchAt("touchStart", q, t),
    move: (q, t) => touchAt("touchMove", q, t),
    up: (q, t) => touchAt("touchEnd", null, t),
  };
  const mouseAt = (type, q, buttons, timestamp) => p.cdp.send("Input.dispatchMouseEvent", {
    type, x: q.x, y: q.y, button: "left", buttons, timestamp,
    clickCount: type === "mouseMoved" ? 0 : 1 });
  const mouse = {
    down: (q, t) => mouseAt("mouseMoved", q, 0, t).then(() => mouseAt("mousePressed", q, 1, t)),
    move: (q, t) => mouseAt("mouseMoved", q, 1, t),
    up: (q, t) => mouseAt("mouseReleased", q, 0, t),
  };
  const released = async (before) => {
    const l = (await lines(/Released particle|Launched particle/)).slice(before);
    return l.length ? l[l.length - 1] : "nothing";
  };
  const speedOf = (line) => {
    const m = line.match(/velocity \[(-?[\d.]+), (-?[\d.]+)\]/);
    return m ? Math.hypot(+m[1], +m[2]) : 0;
  };
  const path = (o) => Array.from({ length: 7 }, (_, k) => ({ x: o.x + 14 * k, y: o.y - 6 * k }));
  const results = {};
  for (const [name, hand, spot] of [["finger", finger, at], ["mouse", mouse, { x: at.x, y: at.y + 150 }]]) {
    let n = await count(/Released particle|Launched particle/);
    await fling(hand, [spot, spot], 700);  // launched at rest
    const launched = await released(n);
    n = await count(/Released particle|Launched particle/);
    await fling(hand, path(spot), 30);
    results[name] = { launched, flung: await released(n) };
  }
  const vf = speedOf(results.finger.flung), vm = speedOf(results.mouse.flung);
  check(/Launched particle .* velocity \[0\.00, 0\.00\]/.test(results.finger.launched) &&
        /Released particle/.test(results.finger.flung) && vf > 0 && vm > 0 &&
        Math.abs(vf - vm) <= 0.3 * vm,
        `a finger's fling launches as the mouse's of the same path: finger ${vf.toFixed(2)} m/s, ` +
        `mouse ${vm.toFixed(2)} m/s (${results.finger.flung}; ${results.mouse.flung})`);
  await p.shot("18-flung");
  // 7. Once a finger has touched, the hints name the panel's buttons, not keys.
  const paused = (await lines(/while paused: .* sets it moving/)).pop() || "nothing said";
  check(/Play sets it moving/.test(paused), `a hint after a finger names the button: ${paused}`);

  // 7. A finger's edit of the box says how to take it back with the panel's Undo (in Time),
  //    not Ctrl+Z: a peg placed, moved, selected and deleted, then the Undo named brings it
  //    back.
  const tools = await reach("section Tools");
  if (tools) await p.tap(tools);
  await p.waitFor("the Tools section", async () => (await p.control("tool Peg")) !== null, 3);
  const pegTool = await reach("tool Peg");
  if (pegTool) await p.tap(pegTool);
  const pegSaid = /Peg placed|Not placed|Obstacle refused/;
  let peg = null;
  for (const spot of [{ x: 640, y: 250 }, { x: 900, y: 250 }, { x: 640, y: 620 },
                      { x: 900, y: 620 }]) {
    const n = await count(pegSaid);
    await p.tap(spot);
    await p.waitFor("the peg", async () => (await count(pegSaid)) > n, 3);
    if (/Peg placed/.test((await lines(pegSaid)).pop() || "")) {
      peg = spot;
      break;
    }
  }
  const placed = (await lines(/Peg placed/)).pop() || "nothing said";
  check(peg && /Peg placed \(Time: Undo undoes it\)$/.test(placed),
        `a peg placed by a finger names the panel's Undo: ${placed}`);
  const selectTool = await reach("tool Select");
  if (selectTool) await p.tap(selectTool);
  const to = peg && { x: peg.x + 40, y: peg.y };
  if (peg) await p.drag(peg, to, 10);
  await p.waitFor("the move", async () => (await count(/Moved the peg/)) > 0, 3);
  const movedSaid = (await lines(/Moved the peg|Not moved/)).pop() || "nothing said";
  check(/Moved the peg \(Time: Undo puts it back\)$/.test(movedSaid),
        `a peg a finger moved names the panel's Undo: ${movedSaid}`);
  if (to) await p.tap(to);
  await p.waitFor("the selection", async () => (await count(/Selected a peg/)) > 0, 3);
  const selectedSaid = (await lines(/Selected a peg/)).pop() || "nothing said";
  check(/Selected a peg: Tools: Delete peg removes it$/.test(selectedSaid),
        `a peg a finger selected names the panel's Delete peg: ${selectedSaid}`);
  const del = await reach("delete obstacle");
  if (del) await p.tap(del);
  await p.waitFor("the removal", async () => (await count(/Removed the peg/)) > 0, 3);
  const removedSaid = (await lines(/Removed the peg/)).pop() || "nothing said";
  check(/Removed the peg \(Time: Undo brings it back\)$/.test(removedSaid),
        `a peg a finger deleted names the panel's Undo: ${removedSaid}`);
  const keysSaid = (await lines(/Peg placed|Moved the peg|Selected a peg|Removed the peg/))
    .filter((l) => /Ctrl\+|Backspace|Delete or/.test(l));
  check(keysSaid.length === 0, `... and no key: ${keysSaid.join("; ") || "none named"}`);
  const undo = await reach("Undo");
  if (undo) await p.tap(undo);
  await p.waitFor("the undo", async () => (await count(/Undone: remove peg/)) > 0, 3);
  check((await count(/Undone: remove peg/)) > 0,
        "the Undo it names is the panel's, and a tap on it brings the peg back: " +
        ((await lines(/Undone|Nothing to undo/)).pop() || "nothing said"));
  await p.shot("18b-peg-undone");

  // 6. The UI scale dragged by a finger: the panel stays open, where it was.
  const scale = await reach("UI scale");
  const scaleSaid = /^\[I\] UI scale \d+ %/;
  const scales0 = await count(scaleSaid);
  if (scale) await p.drag({ x: scale.x - 30, y: scale.y }, { x: scale.x + 90, y: scale.y + 2 }, 12);
  await p.waitFor("the scale", async () => (await count(scaleSaid)) > scales0, 3);
  await p.page.waitForTimeout(800);
  await p.shot("19-scaled");
  const scaled = (await lines(scaleSaid)).pop() || "nothing said";
  check((await count(scaleSaid)) > scales0, `a finger changes the UI scale: ${scaled}`);
  const panelSaid = (await lines(/control panel (folded|covers)/)).pop() || "nothing said";
  const scale1 = await p.control("UI scale");
  check(!/folded/.test(panelSaid) && !(await p.control("open panel")) && scale && scale1 &&
        Math.abs(scale1.y - scale.y) < 80,
        `... and the panel stays open, its slider where the finger left it: ` +
        `${JSON.stringify(scale)} -> ${JSON.stringify(scale1)}; ${panelSaid}`);
  await p.context.close();
}

// ---------------------------------------------------------------------------------------------
// The class's second trial on a phone (390x844, fingers only, paused): the hints name buttons,
// two fingers on the panel's sheet act on nothing under them, nothing covers a reading.
{
  const p = await open({ width: 390, height: 844 }, { deviceScaleFactor: 3, isMobile: true });
  check(await started(p, "?log-controls&seed=7&paused"), "the page starts on a phone (again)");
  await p.page.waitForTimeout(800);
  const lines = async (re) => (await p.log()).filter((l) => re.test(l));
  const count = async (re) => (await lines(re)).length;
  const boxShot = await p.shot("20-phone-readouts");

  // 7. A phone's first words name its buttons: the folded panel opens with >>, not C.
  const folded = (await lines(/control panel is folded/)).pop() || "nothing said";
  check(/: >> opens it/.test(folded), `on a phone the hints name the button, not the key: ${folded}`);

  // 5. Two fingers on the sheet, one of them on a slider: neither the slider nor the box
  //    behind the sheet moves.
  await p.tap(await p.control("open panel"));
  await p.waitFor("the panel", async () => (await p.control("fold panel")) !== null, 3);
  await p.page.waitForTimeout(500);
  const values = /Restitution|Friction|Roughness|Time speed|Gravity|Arrow scale|UI scale/;
  const values0 = await count(values);
  const slider = await p.control("Restitution");
  const a = slider || { x: 100, y: 400 }, b = { x: a.x + 60, y: a.y + 150 };
  await p.touch("touchStart", [[a.x, a.y]]);
  await p.page.waitForTimeout(60);
  await p.touch("touchStart", [[a.x, a.y], [b.x, b.y]]);
  for (let k = 1; k <= 10; k++) {
    await p.touch("touchMove", [[a.x + 8 * k, a.y + 3 * k], [b.x + 8 * k, b.y + 12 * k]]);
    await p.page.waitForTimeout(16);
  }
  await p.touch("touchEnd", []);
  await p.page.waitForTimeout(800);
  await p.shot("21-phone-two-fingers");
  check((await count(values)) === values0,
        "two fingers on the sheet change no slider: " + ((await lines(values)).pop() || "none changed"));
  await p.tap(await p.control("fold panel"));
  await p.page.waitForTimeout(800);
  const boxAfter = await p.shot("22-phone-folded-again");
  const moved = await p.changed(boxShot, boxAfter, { x0: 0, y0: 120, x1: 390, y1: 700 });
  check(moved < 50, `... nor the box behind it (pan, zoom): ${moved} pixels of the box changed`);
  await p.context.close();
}

check(errors.length === 0, "no script errors" + (errors.length ? ": " + errors.join("; ") : ""));
await browser.close();
console.log(failures === 0 ? "classroom: all checks passed" : `classroom: ${failures} check(s) failed`);
process.exit(failures === 0 ? 0 : 1);
