// A new user's trial of the page on a phone and a tablet (tests/web/run.sh runs it after
// classroom_test.mjs), with the browser's own touch events (CDP Input.dispatchTouchEvent in a
// context with touch). It checks, as that user met it:
//   1. a phone (390x844) at a UI scale chosen too large for it (the slider dragged to its end):
//      the panel's sheet and its << stay wholly on screen and a tap on << folds it, after a
//      reload too (the scale is kept in the settings);
//   2. the page's typing field lies over the program's field being typed in, and follows it to
//      another field, so that the browser keeps that spot in view above the on-screen keyboard;
//   3. a phone: with the sheet scrolled down, << is where it was, and one tap folds it;
//   4. on a touch screen (a tablet at the automatic scale) the buttons, check boxes and section
//      headers are at least 40 CSS pixels tall and wide (measured from --log-controls);
//   5. the phone's folded strip: its >> and ? are a finger wide;
//   6. the phone at the largest UI scale its width allows: the HUD stays short, the box keeps
//      most of the screen;
//   7. the tablet's presets are finger-sized rows of the panel, which a finger scrolls;
//   8. a pinch on the box with a particle selected clears nothing (it is no click);
//   9. the Speed slider held by a finger: the "Reaching only" line below it does not move the
//      stopwatch under the finger as it comes;
//  10. the New scene and Save As dialogs: fields, box and buttons at least 40 px tall; a tap into
//      the width field already being typed in, then typing, replaces its number.
// Screenshots are written to PSB_WEB_SHOTS (phone-*.png) for a person to look at.
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

/// A page of the program in a fresh context: `viewport`, fingers only.
async function open(viewport, options = {}) {
  const p = await fingerPage(browser, { viewport, options, shots, prefix: "phone", errors });
  const page = p.page;
  Object.assign(p, {
    /// The panel's control `name`, scrolled into reach by a finger dragged along the panel.
    async reach(name, height, x = 150) {
      for (let k = 0; k < 12; k++) {
        const c = await p.control(name);
        if (!c || (c.y >= 100 && c.y <= height - 80)) return c;
        const by = Math.max(-300, Math.min(300, c.y - height / 2));
        await p.drag({ x, y: height / 2 + by / 2 }, { x, y: height / 2 - by / 2 }, 10);
        await page.waitForTimeout(1000);
      }
      return p.control(name);
    },
  });
  return p;
}

async function started(p, query) {
  await p.page.goto(url + query);
  return p.waitFor("the program", async () => /particles/.test(await p.title()), 60);
}

// ---------------------------------------------------------------------------------------------
// 1 and 3. A phone, fingers only: the UI scale dragged to its end, the sheet scrolled.
{
  const W = 390, H = 844;
  const p = await open({ width: W, height: H }, { deviceScaleFactor: 3, isMobile: true });
  check(await started(p, "?log-controls&seed=7&paused"), "the page starts on a phone");
  await p.page.waitForTimeout(800);
  // 5. The folded strip's buttons are a finger wide (at 6 points' padding either side, 31 px).
  for (const [name, shown] of [["open panel", ">>"], ["About", "?"]]) {
    const e = await p.extent(name);
    check(e && e.x1 - e.x0 >= 40 && e.y1 - e.y0 >= 40,
          `the strip's ${shown} is at least 40x40 px: ${JSON.stringify(e)}`);
  }
  await p.tap(await p.control("open panel"));
  await p.waitFor("the panel", async () => (await p.control("fold panel")) !== null, 3);
  await p.page.waitForTimeout(500);

  // 1. The scale slider dragged to its right end by a finger.
  const scale = await p.reach("UI scale", H, 200);
  const scaleSaid = /^\[I\] UI scale \d+ %/;
  const n0 = (await p.lines(scaleSaid)).length;
  if (scale) await p.drag({ x: scale.x - 20, y: scale.y }, { x: W - 5, y: scale.y + 2 }, 14);
  await p.waitFor("the scale", async () => (await p.lines(scaleSaid)).length > n0, 3);
  await p.page.waitForTimeout(1200);
  await p.shot("1-scale-dragged");
  const said = (await p.lines(scaleSaid)).pop() || "nothing said";
  check(/^\[I\] UI scale [23]\d\d %, shown at 1[56]\d %, the most this page's width allows/
          .test(said), `a scale too large for a phone is used at the most it allows: ${said}`);
  const onScreen = async (what) => {
    const fold = await p.extent("fold panel");
    const sheet = await p.extent("UI scale");
    const whole = fold && fold.x0 >= 0 && fold.x1 <= W && fold.x1 - fold.x0 >= 40 &&
                  fold.y1 - fold.y0 >= 40 && fold.y0 >= 0;
    check(whole, `${what}: << wholly on screen and a finger wide: ${JSON.stringify(fold)}`);
    check(sheet && sheet.x1 <= W, `${what}: the sheet's rows end on screen: ${JSON.stringify(sheet)}`);
    return fold;
  };
  // Folded, the strip's >> is drawn again (logged anew).
  const strips = async () => (await p.lines(/^\[I\] Control open panel at /)).length;
  let fold = await onScreen("at the scale chosen");
  const most = await p.control("UI scale most");
  check(most !== null, "the Show section says the scale is the most the page allows");
  let strips0 = await strips();
  if (fold) await p.tap({ x: (fold.x0 + fold.x1) / 2, y: (fold.y0 + fold.y1) / 2 });
  await p.waitFor("the fold", async () => (await strips()) > strips0, 3);
  check((await strips()) > strips0, "a tap on << folds the sheet");
  await p.shot("2-folded");
  // 6. At the largest scale the width allows the HUD keeps to a few short lines: the box (the
  // default scene's, 7 m square) stands high on the screen and takes the width beside the strip
  // (the full lines wrapped to 12 and left it 260 px, its top at 500 px: its foot at 760).
  await p.page.waitForTimeout(500);
  const fitted = (await p.lines(/^\[I\] View: zoom /)).pop() || "";
  const fit = fitted.match(/zoom ([\d.]+) px\/m, box top-left at \[([\d.-]+), ([\d.-]+)\]/);
  const dpr = await p.page.evaluate(() => devicePixelRatio);  // the view's pixels are the device's
  const side = fit ? 7 * +fit[1] / dpr : 0, boxTop = fit ? +fit[3] / dpr : H;
  const strip = await p.extent("open panel");
  check(fit && side >= 0.9 * (W - (strip ? strip.x1 : 0)) && boxTop + side <= 0.85 * H,
        `at ${said.match(/shown at \d+ %/)} the box keeps the width and the upper part of the ` +
        `screen: ${Math.round(side)} px square, its top at ${Math.round(boxTop)} px (${fitted})`);

  // ... and after a reload (the scale is kept in the browser's settings).
  await p.page.waitForTimeout(1500);  // the settings written
  check(await started(p, "?log-controls&seed=7&paused"), "the page starts again");
  await p.page.waitForTimeout(800);
  const kept = (await p.lines(/^\[I\] UI scale/)).pop();
  await p.tap(await p.control("open panel"));
  await p.waitFor("the panel", async () => (await p.control("fold panel")) !== null, 3);
  await p.page.waitForTimeout(500);
  await p.shot("3-reloaded");
  fold = await onScreen(`after a reload (${kept || "no settings line"})`);

  // 3. Scrolled down, the sheet keeps << where it was, and one tap folds it.
  const top = await p.extent("fold panel");
  const readouts0 = await p.control("section Readouts");
  for (let k = 0; k < 3; k++) {
    await p.drag({ x: 200, y: 700 }, { x: 200, y: 250 }, 14);
    await p.page.waitForTimeout(900);
  }
  const readouts1 = await p.control("section Readouts");
  const after = await p.extent("fold panel");
  await p.shot("4-scrolled");
  check(readouts0 && readouts1 && readouts0.y - readouts1.y > 300,
        `the sheet scrolled: the Readouts ${readouts0 && readouts0.y} -> ${readouts1 && readouts1.y}`);
  check(top && after && after.y0 === top.y0 && after.x0 === top.x0,
        `<< stays where it was: ${JSON.stringify(top)} -> ${JSON.stringify(after)}`);
  strips0 = await strips();
  if (after) await p.tap({ x: (after.x0 + after.x1) / 2, y: (after.y0 + after.y1) / 2 });
  await p.waitFor("the fold", async () => (await strips()) > strips0, 3);
  check((await strips()) > strips0, "one tap on << folds the scrolled sheet");
  await p.shot("5-folded-from-below");
  await p.context.close();
}

// ---------------------------------------------------------------------------------------------
// 2 and 4. A tablet, fingers only, at the automatic scale.
{
  const W = 1024, H = 768;
  const p = await open({ width: W, height: H });
  check(await started(p, "?log-controls&seed=7&paused"), "the page starts on a tablet");
  await p.page.waitForTimeout(500);
  // A first tap on the box: the page knows a finger is its pointer.
  await p.tap({ x: 900, y: 700 });
  await p.page.waitForTimeout(500);

  // 4. Finger-sized targets.
  const names = ["Play/Pause", "Step", "Restart", "Undo", "Stopwatch start", "Stopwatch lap",
                 "Stopwatch reset", "section Show", "Velocity arrows", "Labels", "y up", "Spin",
                 "Grid", "UI scale auto", "fold panel"];
  const small = [];
  for (const name of names) {
    const e = await p.extent(name);
    if (!e || e.y1 - e.y0 < 40 || e.x1 - e.x0 < 40) small.push(`${name} ${JSON.stringify(e)}`);
  }
  const step = await p.extent("Step");
  check(small.length === 0, `every button and box is at least 40 px tall and wide (Step ` +
        `${step && step.x1 - step.x0}x${step && step.y1 - step.y0}): ` +
        (small.join("; ") || "none smaller"));
  await p.shot("6-tablet-targets");

  // 2. The typing field over the field typed in, and following it.
  const typingRect = () => p.page.evaluate(() => {
    const r = document.getElementById("typing").getBoundingClientRect();
    return { x0: r.left, y0: r.top, x1: r.right, y1: r.bottom,
             focused: document.activeElement && document.activeElement.id === "typing" };
  });
  const over = (r, c) => r && c && r.x0 <= c.x && c.x <= r.x1 && r.y0 <= c.y && c.y <= r.y1;
  const scene = await p.reach("section Scene", H);
  if (scene) await p.tap(scene);
  await p.waitFor("the Scene section", async () => (await p.control("title")) !== null, 3);
  const title = await p.reach("title", H);
  if (title) await p.tap(title);
  await p.waitFor("the typing field", async () => (await typingRect()).focused, 3);
  await p.page.waitForTimeout(300);
  const atTitle = await typingRect();
  const titleNow = await p.control("title");
  check(atTitle.focused && over(atTitle, titleNow) && atTitle.y0 > 20,
        `the typing field lies over the title field: ${JSON.stringify(atTitle)}, the field at ` +
        JSON.stringify(titleNow));
  await p.page.keyboard.press("Enter");
  await p.page.waitForTimeout(400);
  await p.tap(await p.control("section Scene"));  // folded again
  await p.page.waitForTimeout(300);
  const tools = await p.reach("section Tools", H);
  if (tools) await p.tap(tools);
  await p.waitFor("the Tools section", async () => (await p.control("launch mass")) !== null, 3);
  const mass = await p.reach("launch mass", H);
  if (mass) await p.tap(mass);
  await p.waitFor("the typing field", async () => (await typingRect()).focused, 3);
  await p.page.waitForTimeout(300);
  const atMass = await typingRect();
  const massNow = await p.control("launch mass");
  await p.shot("7-typing-mass");
  check(atMass.focused && over(atMass, massNow) && Math.abs(atMass.y0 - atTitle.y0) > 5,
        `... and follows the field typed in to the launch mass: ${JSON.stringify(atMass)}, the ` +
        `field at ${JSON.stringify(massNow)}`);
  await p.page.keyboard.press("Escape");
  await p.page.waitForTimeout(300);

  // 10. The dialogs: finger-sized, and a tap into the width field (already being typed in, its
  // text selected) then typing replaces the width, as what it shows says (it read 710).
  // Whether the Scene section is open now: in the last list of the panel's controls (the log
  // has every list), its header is followed by its presets.
  const sceneIsOpen = async () => {
    const l = await p.lines(/^\[I\] Control /);
    const at = l.map((x) => /^\[I\] Control section Scene spans /.test(x)).lastIndexOf(true);
    return at >= 0 && at + 1 < l.length && /^\[I\] Control preset /.test(l[at + 1]);
  };
  if (!(await sceneIsOpen())) {
    const sceneHeader = await p.reach("section Scene", H);
    if (sceneHeader) await p.tap(sceneHeader);
    await p.waitFor("the Scene section", sceneIsOpen, 3);
  }
  const newScene = await p.reach("New scene", H);
  if (newScene) await p.tap(newScene);
  await p.waitFor("the New scene dialog", async () => (await p.control("dialog width")) !== null, 3);
  await p.page.waitForTimeout(300);
  const measure = async (names) => {
    const small = [];
    for (const name of names) {
      const e = await p.extent(name);
      if (!e || e.y1 - e.y0 < 40 || e.x1 - e.x0 < 40) small.push(`${name} ${JSON.stringify(e)}`);
    }
    return small;
  };
  const smallNew = await measure(["dialog width", "dialog height", "dialog gravity",
                                  "dialog walls", "dialog Create", "dialog Cancel"]);
  check(smallNew.length === 0, `the New scene dialog's fields, box and buttons are at least ` +
        `40 px: ${smallNew.join("; ") || "none smaller"}`);
  await p.shot("9-new-scene");
  await p.tap(await p.control("dialog width"));
  await p.page.waitForTimeout(300);
  await p.page.keyboard.type("10");
  await p.page.waitForTimeout(300);
  await p.tap(await p.control("dialog height"));
  await p.page.waitForTimeout(300);
  await p.page.keyboard.type("5");
  await p.page.waitForTimeout(300);
  await p.shot("10-new-scene-typed");
  await p.tap(await p.control("dialog Create"));
  await p.waitFor("the new scene", async () => (await p.lines(/New scene: an empty box/)).length > 0, 3);
  const made = (await p.lines(/New scene: an empty box/)).pop() || "no new scene";
  check(/an empty box 10(\.0)? m x 5(\.00)? m/.test(made),
        `a tap into the width field, then 10; into the height, then 5: ${made}`);
  const saveAs = await p.reach("Save As", H);
  if (saveAs) await p.tap(saveAs);
  await p.waitFor("the Save As dialog", async () => (await p.control("dialog file name")) !== null, 3);
  await p.page.waitForTimeout(300);
  const smallSave = await measure(["dialog file name", "dialog Save", "dialog Cancel"]);
  check(smallSave.length === 0, `the Save As dialog's field and buttons are at least 40 px: ` +
        (smallSave.join("; ") || "none smaller"));
  await p.shot("11-save-as");
  const cancel = await p.control("dialog Cancel");
  if (cancel) await p.tap(cancel);
  await p.page.waitForTimeout(300);
  // 7. The presets: rows of the panel a finger's height, and a finger dragged up from one
  // scrolls the panel (a list of their own, 19 px rows, took the finger's scroll).
  await p.waitFor("the presets", async () => (await p.control("preset Newton's cradle")) !== null, 3);
  const cradle = await p.reach("preset Newton's cradle", H);
  const cradleRow = await p.extent("preset Newton's cradle");
  check(cradleRow && cradleRow.y1 - cradleRow.y0 >= 40,
        `a preset's row is at least 40 px tall: ${JSON.stringify(cradleRow)}`);
  const newScene0 = await p.control("New scene");
  if (cradle) {
    // Slowly, a frame or more a step (a drag whose moves all came within one slow frame was
    // not seen as one).
    await p.touch("touchStart", [[cradle.x, cradle.y]]);
    for (let k = 1; k <= 15; k++) {
      await p.touch("touchMove", [[cradle.x, cradle.y - 10 * k]]);
      await p.page.waitForTimeout(50);
    }
    await p.touch("touchEnd", []);
  }
  await p.page.waitForTimeout(1000);
  const newScene1 = await p.control("New scene");
  check(newScene0 && newScene1 && newScene0.y - newScene1.y >= 90,
        `a finger dragged up from a preset scrolls the panel: New scene ${newScene0 && newScene0.y}` +
        ` -> ${newScene1 && newScene1.y}`);

  // 8. A particle tapped is selected; then two fingers pinch right of the box: the first
  // finger's press ends as the pinch begins, not as a click ("Selection cleared").
  const original = await p.reach("preset The original's default", H);
  if (original) await p.tap(original);
  await p.waitFor("the original", async () => /original/.test(await p.title()), 5);
  await p.page.waitForTimeout(800);
  const picked0 = (await p.lines(/^\[I\] Selected particle/)).length;
  await p.tap({ x: 877, y: 382 });  // the original's orange disc at the automatic scale
  await p.waitFor("the selection", async () => (await p.lines(/^\[I\] Selected particle/)).length > picked0, 3);
  check((await p.lines(/^\[I\] Selected particle/)).length > picked0, "a tap selects a particle");
  const cleared0 = (await p.lines(/Selection cleared/)).length;
  await p.touch("touchStart", [[990, 330]]);
  await p.page.waitForTimeout(60);
  await p.touch("touchStart", [[990, 330], [1000, 470]]);
  for (let k = 1; k <= 8; k++) {
    await p.touch("touchMove", [[990, 330 - 8 * k], [1000, 470 + 8 * k]]);
    await p.page.waitForTimeout(16);
  }
  await p.touch("touchEnd", []);
  await p.page.waitForTimeout(600);
  const cleared = await p.lines(/Selection cleared/);
  check(cleared.length === cleared0,
        `a pinch clears no selection: ${cleared.slice(cleared0).join("; ") || "nothing said"}`);

  await p.context.close();
}

// ---------------------------------------------------------------------------------------------
// 9. A tablet, Brownian motion (1501 particles, key 8), running at x8, more than this machine
// computes.
{
  const W = 1024, H = 768;
  const p = await open({ width: W, height: H });
  check(await started(p, "?log-controls&seed=7&paused"), "the page starts on a tablet again");
  await p.page.waitForTimeout(500);
  await p.tap({ x: 1000, y: 740 });  // a finger: the page is a touch screen's
  await p.page.keyboard.press("8");
  await p.waitFor("Brownian motion", async () => /Brownian/.test(await p.title()), 5);
  await p.page.waitForTimeout(1500);
  // Running, the Speed slider dragged to its end and held there by a finger: the line that
  // says the speed is not reached keeps off the stopwatch below until the finger lifts.
  await p.page.keyboard.press("Space");
  check(await p.waitFor("the run", async () => !/PAUSED/.test(await p.title()), 5),
        `Space runs Brownian motion: ${await p.title()}`);
  await p.page.waitForTimeout(800);
  const speed = await p.reach("Speed", H);
  const speedRow = await p.extent("Speed");
  const behind0 = (await p.control("Speed reached")) !== null;
  let watch0 = null;
  if (speed && speedRow) {
    const from = { x: speedRow.x0 + 10, y: speed.y };
    await p.touch("touchStart", [[from.x, from.y]]);
    // Where the stopwatch is once the finger is down (under load the line may come and go at
    // x1 before it).
    await p.page.waitForTimeout(300);
    watch0 = await p.extent("Stopwatch start");
    for (let k = 1; k <= 12; k++) {
      await p.touch("touchMove", [[from.x + (speedRow.x1 + 40 - from.x) * k / 12, from.y]]);
      await p.page.waitForTimeout(16);
    }
    await p.page.waitForTimeout(3000);  // x8: too much to compute
  }
  const watchHeld = await p.extent("Stopwatch start");
  await p.touch("touchEnd", []);
  await p.page.waitForTimeout(1500);
  const behind = (await p.control("Speed reached")) !== null;
  await p.shot("8-speed-let-go");
  check(watch0 && watchHeld && watch0.y0 === watchHeld.y0,
        `the stopwatch stays put under a finger holding the Speed slider: ` +
        `${JSON.stringify(watch0)} -> ${JSON.stringify(watchHeld)}` +
        (behind0 ? " (the line was there before)" : behind ? " (the line came at the lift)" : " (no line came)"));
  // A machine that computes x8 of it (a quiet one does) shows no line: nothing to check then.
  if (behind0 || behind || !watch0) {
    check(behind, "at x8 the panel says the speed is not reached (after the lift)");
  } else {
    console.log("skip this machine kept up with x8: no line to hold under the finger");
  }

  await p.context.close();
}

check(errors.length === 0, "no script errors" + (errors.length ? ": " + errors.join("; ") : ""));
await browser.close();
console.log(failures === 0 ? "phone: all checks passed" : `phone: ${failures} check(s) failed`);
process.exit(failures === 0 ? 0 : 1);
