// The page's frame-time benchmark in headless Chromium: ?bench=N for each N given, at a
// 1200x800 page, printing the program's line (mean step and draw times, as the desktop's
// --bench prints them) with the frame rate the browser's animation frames reached.
//   tests/web/run.sh bench 10000 50000     (scripts/web.sh bench builds the page first)
import { chromium, launchOptions } from "./chromium.mjs";

const url = process.env.PSB_WEB_URL;
const frames = process.env.PSB_BENCH_FRAMES || "300";
const browser = await chromium.launch(launchOptions());
let failed = false;
for (const n of process.argv.slice(2)) {
  const page = await browser.newPage({ viewport: { width: 1200, height: 800 } });
  await page.goto(`${url}?bench=${n}&frames=${frames}`);
  try {
    await page.waitForFunction(() => window.psbResult !== undefined, null, { timeout: 600000 });
    console.log(await page.evaluate(() => window.psbResult));
  } catch (e) {
    console.log(`bench ${n}: no result (${e.message.split("\n")[0]})`);
    failed = true;
  }
  await page.close();
}
await browser.close();
process.exit(failed ? 1 : 0);
