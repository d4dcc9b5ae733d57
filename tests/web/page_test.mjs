// The web build's end-to-end test: the page in headless Chromium (tests/web/run.sh serves it
// and sets PSB_WEB_URL). It checks, as a user would see it:
//   1. the default scene appears (coloured particles in the box) and moves (pixels change);
//   2. a mouse drag on empty space launches a particle (the title's count goes up by one), and
//      paused, a particle flung at a hand's pace keeps its speed;
//   3. a preset opens from the control panel (the title names it);
//   4. Save downloads a scene file, which the desktop runner (particle-sim) reads back, and the
//      message names the download, not the page's folder;
//   5. a malformed scene opened with Open is refused with the file's name and the problem, and
//      the program goes on; the saved scene opened the same way opens;
//   6. a one-finger touch drag launches a particle, two fingers pinch-zoom the view;
//   7. what is shown is kept in the browser's storage over a reload, and a broken entry there
//      is ignored with a message;
//   8. a browser without WebAssembly gets a clear message; one without WebGL (no GPU) runs the
//      page with the software renderer.
// Screenshots of each step are written to PSB_WEB_SHOTS for a person to look at.
import { execFileSync } from "child_process";
import fs from "fs";
import path from "path";

import { chromium, launchOptions } from "./chromium.mjs";

const url = process.env.PSB_WEB_URL;
const shots = process.env.PSB_WEB_SHOTS;
const sim = process.env.PSB_SIM;
fs.mkdirSync(shots, { recursive: true });

let failures = 0;
function check(ok, what) {
  console.log(`${ok ? "ok  " : "FAIL"} ${what}`);
  if (!ok) failures++;
}

const browser = await chromium.launch(launchOptions());
const context = await browser.newContext({
  viewport: { width: 1200, height: 800 }, acceptDownloads: true, hasTouch: true,
});
const page = await context.newPage();
const errors = [];
page.on("pageerror", (e) => errors.push(e.message));

const log = () => page.evaluate(() => window.psbLog.slice());
const title = () => page.title();
const count = async () => {
  const m = (await title()).match(/ (\d+) particles?/);
  return m ? +m[1] : NaN;
};
async function shot(name) {
  const png = await page.screenshot({ path: path.join(shots, name + ".png") });
  return png.toString("base64");
}
async function waitFor(what, test, seconds = 10) {
  for (let t = 0; t < seconds * 10; t++) {
    if (await test()) return true;
    await page.waitForTimeout(100);
  }
  console.log(`  (timed out waiting for ${what})`);
  return false;
}
/// The panel's control called `name`, from --log-controls' lines: its centre, window points.
async function control(name) {
  const lines = (await log()).filter((l) => l.startsWith(`[I] Control ${name} at `));
  if (lines.length === 0) throw new Error(`no control "${name}" logged`);
  const m = lines[lines.length - 1].match(/ at (-?\d+) (-?\d+)$/);
  return { x: +m[1], y: +m[2] };
}
async function click(name) {
  // Wheeled into view first: after a finger has touched the page its panel's targets are a
  // finger's size, and the Scene section's buttons are below an 800-pixel window's fold.
  let c = await control(name);
  for (let k = 0; k < 20 && (c.y < 40 || c.y > 760); k++) {
    await page.mouse.move(301, 400);  // over the panel's scroll bar, not a list in it
    await page.mouse.wheel(0, c.y > 760 ? 200 : -200);
    await page.waitForTimeout(250);
    c = await control(name);
  }
  await page.mouse.click(c.x, c.y);
  await page.waitForTimeout(300);
}
/// Pixel statistics of screenshots (base64 PNGs), computed in the page.
function pixels(op, a, b, rect) {
  return page.evaluate(async ([op, a, b, rect]) => {
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
    const A = await load(a);
    const B = b ? await load(b) : null;
    const at = (I, x, y) => (y * I.width + x) * 4;
    if (op === "changed") {
      let n = 0;
      for (let y = rect.y0; y < rect.y1; y++)
        for (let x = rect.x0; x < rect.x1; x++) {
          const i = at(A, x, y);
          const d = Math.abs(A.data[i] - B.data[i]) + Math.abs(A.data[i + 1] - B.data[i + 1]) +
                    Math.abs(A.data[i + 2] - B.data[i + 2]);
          if (d > 30) n++;
        }
      return n;
    }
    if (op === "colored") {
      let n = 0;
      for (let y = rect.y0; y < rect.y1; y++)
        for (let x = rect.x0; x < rect.x1; x++) {
          const i = at(A, x, y);
          const r = A.data[i], g = A.data[i + 1], bl = A.data[i + 2];
          if (Math.max(r, g, bl) - Math.min(r, g, bl) > 60) n++;
        }
      return n;
    }
    if (op === "empty") {  // the first square of rect.size with nothing drawn in it
      const s = rect.size;
      for (let y = rect.y0; y + s < rect.y1; y += 10)
        for (let x = rect.x0; x + s < rect.x1; x += 10) {
          let dark = true;
          for (let v = y; v < y + s && dark; v += 2)
            for (let u = x; u < x + s && dark; u += 2) {
              const i = at(A, u, v);
              if (A.data[i] + A.data[i + 1] + A.data[i + 2] > 40) dark = false;
            }
          if (dark) return { x: x + s / 2, y: y + s / 2 };
        }
      return null;
    }
    if (op === "box") {  // the white outline's bounding box
      let x0 = 1e9, y0 = 1e9, x1 = -1, y1 = -1;
      for (let y = rect.y0; y < rect.y1; y++)
        for (let x = rect.x0; x < rect.x1; x++) {
          const i = at(A, x, y);
          if (A.data[i] > 240 && A.data[i + 1] > 240 && A.data[i + 2] > 240) {
            x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y);
          }
        }
      return { x0, y0, x1, y1 };
    }
    return null;
  }, [op, a, b, rect]);
}

// The box, right of the panel, below the HUD's lines.
const scene = { x0: 320, y0: 70, x1: 1190, y1: 760 };
// Inside the walled box (442..1067 x 104..729 at 1200 x 800 under the HUD's band), with a margin:
// a spot found right of the box is empty too, and a particle launched there is put inside it.
const inBox = { x0: 460, y0: 120, x1: 1040, y1: 700, size: 90 };

// 1. The default scene appears and moves.
await page.goto(url + "?log-controls&seed=7");
check(await waitFor("the program", async () => /particles/.test(await title()), 60),
      "the page starts: title " + JSON.stringify(await title()));
const loadingHidden = await page.evaluate(
  () => getComputedStyle(document.getElementById("loading")).display === "none");
check(loadingHidden, "the loading indicator is gone once the program runs");
await page.waitForTimeout(500);
const first = await shot("1-default-scene");
await page.waitForTimeout(1000);
const second = await shot("1-default-scene-later");
const colored = await pixels("colored", first, null, scene);
check(colored > 2000, `the default scene's particles are drawn (${colored} coloured pixels)`);
const moved = await pixels("changed", first, second, scene);
check(moved > 500, `the scene moves: ${moved} pixels changed in 1 s`);

// 2. A mouse drag on empty space launches a particle. Paused, so that the spot stays empty.
await page.keyboard.press("Space");
await waitFor("the pause", async () => /PAUSED/.test(await title()));
const paused = await shot("2-paused");
const spot = await pixels("empty", paused, null, inBox);
check(spot !== null, `an empty spot in the box: ${JSON.stringify(spot)}`);
const before = await count();
await page.mouse.move(spot.x, spot.y);
await page.mouse.down();
for (let k = 1; k <= 10; k++) await page.mouse.move(spot.x + 4 * k, spot.y + 2 * k);
await page.mouse.up();
await waitFor("the launch", async () => (await count()) === before + 1);
check((await count()) === before + 1, `a mouse drag launches a particle: ${before} -> ${await count()}`);
await shot("2-launched");
// Paused, a particle grabbed and flung at a hand's pace keeps its speed for when time runs.
// The program lets a particle go at rest when the hand stood still for 100 ms before the
// release; on a loaded machine the driver's own pauses between its events can be that long, so
// a release at rest is tried again (at most three times, from where the particle was left).
let flung = "nothing";
let from = { x: spot.x, y: spot.y };
for (let attempt = 0; attempt < 3 && !/Flung at/.test(flung); attempt++) {
  const seen = (await log()).length;
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let k = 1; k <= 8; k++) {
    await page.mouse.move(from.x - 5 * k, from.y + 3 * k);
    await page.waitForTimeout(20);
  }
  await page.mouse.up();
  await waitFor("the fling", async () =>
    (await log()).slice(seen).some((l) => /Flung at|Moved while paused/.test(l)));
  flung = (await log()).slice(seen).filter((l) => /Flung at|Moved while paused/.test(l)).pop() || "nothing";
  from = { x: from.x - 40, y: from.y + 24 };
}
check(/Flung at .* while paused/.test(flung), `a paused fling keeps its speed: ${flung}`);

// 3. A preset opens from the panel.
await click("section Scene");
await waitFor("the presets", async () =>
  (await log()).some((l) => l.startsWith("[I] Control preset ")));
const presets = (await log()).filter((l) => /^\[I\] Control preset .* at -?\d+ -?\d+$/.test(l))
  .map((l) => l.match(/^\[I\] Control preset (.*) at /)[1]);
check(!(await log()).some((l) => l.startsWith("[I] Control section Video")),
      "the panel has no Video section (recording is desktop-only)");
const preset = presets[1];
await click("preset " + preset);
await waitFor("the preset", async () => (await title()).includes(preset));
check((await title()).includes(preset), `the preset "${preset}" opens: ${await title()}`);
await page.waitForTimeout(500);
await shot("3-preset");

// 4. Save downloads a scene file that particle-sim reads back.
const download = page.waitForEvent("download", { timeout: 15000 });
await click("Save");
await page.waitForTimeout(300);
await shot("4-save-dialog");
// The Save As dialog's proposal. Held for a few frames: the panel (Dear ImGui 1.86) reads a key
// that goes down and up within one frame as never pressed, and a person's press is longer.
await page.keyboard.down("Enter");
await page.waitForTimeout(100);
await page.keyboard.up("Enter");
let saved = null;
try {
  const d = await download;
  saved = path.join(shots, d.suggestedFilename());
  await d.saveAs(saved);
} catch (e) {
  console.log("  " + e.message.split("\n")[0]);
  console.log("  the program's last lines:\n    " + (await log()).slice(-8).join("\n    "));
}
check(saved !== null && saved.endsWith(".json"), `Save downloads ${saved && path.basename(saved)}`);
await waitFor("the download message", async () =>
  (await log()).some((l) => l.startsWith("[I] Downloaded ")));
check((await log()).some((l) => saved && l.startsWith("[I] Downloaded " + path.basename(saved))),
      "the program says where the file went: " +
      ((await log()).find((l) => l.startsWith("[I] Downloaded ")) || "nothing"));
const savedLine = (await log()).find((l) => /^\[I\] Saved \d+ particles/.test(l)) || "nothing";
check(saved && savedLine.endsWith(" as " + path.basename(saved)) && !savedLine.includes("/files"),
      "the save names the download, not the page's folder: " + savedLine);
if (saved && sim) {
  let ok = true, out = "";
  try {
    out = execFileSync(sim, [saved, "--duration", "0.1", "--report", "-"], { encoding: "utf8" });
  } catch (e) {
    ok = false;
    out = String(e.stderr || e.message);
  }
  const report = ok ? JSON.parse(out) : null;
  check(ok && report !== null, `particle-sim reads the downloaded scene back` +
        (ok ? "" : ": " + out.trim()));
} else {
  check(false, "particle-sim reads the downloaded scene back (PSB_SIM not set)");
}
await shot("4-saved");

// 5. Open: a malformed scene is refused with the desktop's message; the saved one opens.
async function upload(name, content) {
  const chooser = page.waitForEvent("filechooser", { timeout: 10000 });
  await click("Open");
  const fc = await chooser;
  await fc.setFiles({ name, mimeType: "application/json", buffer: Buffer.from(content) });
}
const titleBefore = await title();
await upload("broken.json", '{"version": 1, "particles": [ {"x": 1, ');
await waitFor("the refusal", async () => (await log()).some((l) => l.includes("broken.json")));
const refusal = (await log()).filter((l) => l.includes("broken.json")).pop() || "";
check(/broken\.json/.test(refusal) && /\[E\]|\[W\]/.test(refusal),
      `a malformed scene is refused with a message: ${refusal}`);
await page.waitForTimeout(300);
await shot("5-malformed-refused");
check((await title()) === titleBefore, "the scene shown stays after the refusal");
await upload("negative-mass.json", JSON.stringify({
  version: 1, world: { width: 10, height: 10 },
  particles: [{ x: 5, y: 5, vx: 0, vy: 0, mass: -1, radius: 0.5 }] }));
await waitFor("the refusal", async () =>
  (await log()).some((l) => l.includes("negative-mass.json") && l.includes("mass")));
const massRefusal = (await log()).filter((l) => l.includes("negative-mass.json")).pop() || "";
check(/particles\[0\]\.mass/.test(massRefusal),
      `a scene with a bad value names the value: ${massRefusal}`);
if (saved) {
  await upload("round-trip.json", fs.readFileSync(saved));
  await waitFor("the upload", async () => (await log()).some((l) => l.includes("round-trip.json")));
  // The program's own line, not the panel's status lines (--log-controls).
  const opened = (await log())
    .filter((l) => l.includes("round-trip.json") && !l.startsWith("[I] Control ")).pop() || "";
  check(/Opened|opened/.test(opened) && (await title()).includes(preset),
        `the saved scene opens again: ${opened}`);
}

// 6. Touch: one finger launches (like the left button); two fingers pinch-zoom.
const cdp = await context.newCDPSession(page);
const touch = (type, points) => cdp.send("Input.dispatchTouchEvent", {
  type, touchPoints: points.map(([x, y], id) => ({ x, y, id })) });
if (!/PAUSED/.test(await title())) await page.keyboard.press("Space");
await waitFor("the pause", async () => /PAUSED/.test(await title()));
const beforeTouch = await shot("6-before-touch");
const tspot = await pixels("empty", beforeTouch, null, inBox);
const touchCount = await count();
if (tspot) {
  await touch("touchStart", [[tspot.x, tspot.y]]);
  for (let k = 1; k <= 10; k++) {
    await touch("touchMove", [[tspot.x + 5 * k, tspot.y - 3 * k]]);
    await page.waitForTimeout(16);
  }
  await touch("touchEnd", []);
  await waitFor("the touch launch", async () => (await count()) === touchCount + 1);
}
check((await count()) === touchCount + 1,
      `a one-finger drag launches a particle: ${touchCount} -> ${await count()}`);
const beforePinch = await shot("6-touch-launched");
const box0 = await pixels("box", beforePinch, null, scene);
const cx = (box0.x0 + box0.x1) / 2, cy = (box0.y0 + box0.y1) / 2;
const pinchCount = await count();
// Fingers 200 px apart come to 110: the view zooms out by about that ratio about their midpoint.
await touch("touchStart", [[cx - 100, cy], [cx + 100, cy]]);
for (let k = 1; k <= 9; k++) {
  await touch("touchMove", [[cx - 100 + 5 * k, cy], [cx + 100 - 5 * k, cy]]);
  await page.waitForTimeout(16);
}
await touch("touchEnd", []);
await page.waitForTimeout(300);
const afterPinch = await shot("6-pinched");
const box1 = await pixels("box", afterPinch, null, scene);
const ratio = (box1.x1 - box1.x0) / (box0.x1 - box0.x0);
check(ratio > 0.45 && ratio < 0.7,
      `two fingers closing zoom out: the box ${box0.x1 - box0.x0} -> ${box1.x1 - box1.x0} px wide`);
check((await count()) === pinchCount, "a pinch launches nothing");

// 7. Settings kept over a reload; a broken entry ignored with a message.
const started = () => waitFor("the program", async () => /particles/.test(await title()), 60);
await page.keyboard.press("s");  // labels on
await waitFor("the settings", () => page.evaluate(() => {
  try { return Module.FS.readFile("/settings/settings.json", { encoding: "utf8" }).includes('"labels": true'); }
  catch (e) { return false; }
}));
await page.waitForTimeout(500);  // the storage is written in the background
await page.reload();
await started();
await waitFor("the settings applied", async () => (await log()).some((l) => l.includes("Labels on")));
check((await log()).some((l) => l.includes("Labels on")), "labels shown again after a reload");
await page.waitForTimeout(500);
await shot("7-settings-kept");
await page.evaluate(() => new Promise((done) => {
  Module.FS.writeFile("/settings/settings.json", '{"show": {"labels": ');
  Module.FS.syncfs(false, done);
}));
await page.reload();
await started();
await waitFor("the warning", async () => (await log()).some((l) => l.includes("settings kept")));
const warning = (await log()).find((l) => l.includes("settings kept")) || "";
check(/^\[W\] The settings kept in this browser were ignored/.test(warning),
      `a broken settings entry is ignored with a message: ${warning}`);
await page.waitForTimeout(300);
await shot("7-settings-broken");

// 8. No WebAssembly: a message instead of the program. No GPU: the software renderer.
const bare = await browser.newPage();
await bare.addInitScript(() => {
  Object.defineProperty(window, "WebAssembly", { value: undefined, configurable: true });
});
await bare.goto(url);
const noWasm = await bare.evaluate(() => document.getElementById("problem").innerText);
check(/cannot run WebAssembly/.test(noWasm), `without WebAssembly the page says so: ${noWasm}`);
await bare.screenshot({ path: path.join(shots, "8-no-webassembly.png") });
await bare.close();
const noGpu = await chromium.launch({ ...launchOptions(), args: ["--disable-gpu", "--disable-3d-apis"] });
const plain = await noGpu.newPage({ viewport: { width: 900, height: 600 } });
const plainLog = [];
plain.on("console", (m) => plainLog.push(m.text()));
await plain.goto(url);
for (let t = 0; t < 300 && !/particles/.test(await plain.title()); t++) await plain.waitForTimeout(100);
await plain.waitForTimeout(500);
await plain.screenshot({ path: path.join(shots, "8-no-webgl.png") });
check(/particles/.test(await plain.title()) && plainLog.some((l) => /Renderer: software/.test(l)),
      `without WebGL the software renderer draws: ${plainLog.find((l) => /Renderer/.test(l))}`);
await noGpu.close();

check(errors.length === 0, "no script errors" + (errors.length ? ": " + errors.join("; ") : ""));
await browser.close();
console.log(failures === 0 ? "web: all checks passed" : `web: ${failures} check(s) failed`);
process.exit(failures === 0 ? 0 : 1);
