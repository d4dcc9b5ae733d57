// Headless Chromium for the web tests: Debian's chromium, driven by playwright-core (from
// build/web-test/node_modules, see run.sh).
import { createRequire } from "module";

const require = createRequire(process.env.NODE_PATH + "/");
export const { chromium } = require("playwright-core");

export function launchOptions() {
  return {
    executablePath: process.env.PSB_CHROMIUM || "/usr/bin/chromium",
    // No GPU here: WebGL on SwiftShader, the software renderer Chromium ships.
    args: ["--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--ignore-gpu-blocklist"],
  };
}
