// A page of the program in a fresh browser context, driven by fingers: the browser's own touch
// events (CDP Input.dispatchTouchEvent, not mouse stand-ins), the program's log and the panel's
// controls as --log-controls writes them. Shared by classroom_test.mjs and phone_test.mjs.
import path from "path";

/// `viewport`, touch on (`options` go to the context); page errors appended to `errors`;
/// screenshots as SHOTS/PREFIX-NAME.png.
export async function fingerPage(browser, { viewport, options = {}, shots, prefix, errors }) {
  const context = await browser.newContext({ viewport, hasTouch: true, ...options });
  const page = await context.newPage();
  page.on("pageerror", (e) => errors.push(e.message));
  const cdp = await context.newCDPSession(page);
  const p = {
    page, context, cdp,
    log: () => page.evaluate(() => window.psbLog.slice()),
    title: () => page.title(),
    /// A screenshot, also returned as a base64 PNG.
    async shot(name) {
      return (await page.screenshot({ path: path.join(shots, `${prefix}-${name}.png`) }))
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
    async lines(re) {
      return (await p.log()).filter((l) => re.test(l));
    },
    /// The panel's control `name` from --log-controls: its centre, CSS pixels.
    async control(name) {
      const l = await p.lines(new RegExp(`^\\[I\\] Control ${escape(name)} at `));
      if (l.length === 0) return null;
      const m = l[l.length - 1].match(/ at (-?\d+) (-?\d+)$/);
      return { x: +m[1], y: +m[2] };
    },
    /// Its extent, CSS pixels: { x0, y0, x1, y1 }.
    async extent(name) {
      const l = await p.lines(new RegExp(`^\\[I\\] Control ${escape(name)} spans `));
      if (l.length === 0) return null;
      const m = l[l.length - 1].match(/ spans (-?\d+) (-?\d+) (-?\d+) (-?\d+)$/);
      return { x0: +m[1], y0: +m[2], x1: +m[3], y1: +m[4] };
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
  };
  return p;
}

function escape(s) {
  return s.replace(/[.*+?^${}()|[\]\\]/g, "\\$&");
}
