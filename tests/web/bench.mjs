// The page's frame-time benchmark in headless Chromium: ?bench=N for each N given, at a
// 1200x800 page, printing the program's line (mean step and draw times, as the desktop's
// --bench prints them) and the frame rate the browser's animation frames reached. Chromium runs
// without its frame-rate limit, so that the rate is what the machine can do rather than the
// display's, in two set-ups:
//   webgl     WebGL on SwiftShader (Chromium's software GPU; what a browser without a usable
//             GPU driver does), the page's default renderer (SDL's OpenGL ES 2)
//   no-gpu    Chromium with --disable-gpu --disable-3d-apis: no WebGL, so the page draws with
//             SDL's software renderer on a 2-D canvas, composited on the CPU
//   tests/web/run.sh bench 10000 50000     (scripts/web.sh bench builds the page first)
import { chromium, launchOptions } from "./chromium.mjs";

const url = process.env.PSB_WEB_URL;
const frames = process.env.PSB_BENCH_FRAMES || "300";
const unlimited = ["--disable-gpu-vsync", "--disable-frame-rate-limit"];
const setups = {
  webgl: [...launchOptions().args, ...unlimited],
  "no-gpu": ["--disable-gpu", "--disable-3d-apis", ...unlimited],
};
let failed = false;
for (const [name, args] of Object.entries(setups)) {
  const browser = await chromium.launch({ ...launchOptions(), args });
  for (const n of process.argv.slice(2)) {
    const page = await browser.newPage({ viewport: { width: 1200, height: 800 } });
    await page.goto(`${url}?bench=${n}&frames=${frames}`);
    try {
      await page.waitForFunction(() => window.psbResult !== undefined, null, { timeout: 600000 });
      console.log(`${name}: ${await page.evaluate(() => window.psbResult)}`);
    } catch (e) {
      console.log(`${name}: bench ${n}: no result (${e.message.split("\n")[0]})`);
      failed = true;
    }
    await page.close();
  }
  await browser.close();
}
process.exit(failed ? 1 : 0);
