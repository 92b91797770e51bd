// End-to-end check of `lispcad serve` in a real browser (Debian's chromium, headless, through
// playwright-core): the drawing is drawn, a saved edit updates the page without a reload, a
// broken script shows its error over the drawing that stays. Prints one JSON line of figures.
//
//   node preview.mjs URL SCRIPT SCREENSHOT.png
//
// With LISPCAD_LATENCY_RUNS=N it only measures: N saves of SCRIPT (re-written unchanged but
// with a counter comment) and the time from each save to the page's new drawing.

import { chromium } from "playwright-core";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";

const [url, script, shot] = process.argv.slice(2);
const profile = fs.mkdtempSync(path.join(os.tmpdir(), "lispcad-chromium-"));
const ctx = await chromium.launchPersistentContext(profile, {
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  headless: true,
  args: [
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
  ],
  viewport: { width: 1000, height: 700 },
});
const fail = async (msg) => {
  console.error("FAIL: " + msg);
  await ctx.close();
  fs.rmSync(profile, { recursive: true, force: true });
  process.exit(1);
};
try {
  const page = ctx.pages()[0] || (await ctx.newPage());
  const errors = [];
  page.on("pageerror", (e) => errors.push(String(e)));
  await page.goto(url);
  await page.waitForFunction(() => document.body.dataset.drawn === document.body.dataset.runs
    && Number(document.body.dataset.runs) >= 1, null, { timeout: 20000 });
  const original = fs.readFileSync(script, "utf8");
  // The page must not reload: a marker set now survives every update.
  await page.evaluate(() => { window.__marker = 42; });

  const drawn = (needle) => page.waitForFunction(
    (n) => (document.querySelector("#view svg")?.innerHTML || "").includes(n), needle, { timeout: 20000 });

  if (process.env.LISPCAD_LATENCY_RUNS) {
    const n = Number(process.env.LISPCAD_LATENCY_RUNS);
    const times = [];
    for (let i = 1; i <= n; i++) {
      const runs = Number(await page.evaluate(() => document.body.dataset.drawn));
      const t0 = performance.now();
      fs.writeFileSync(script, original + `\n; save ${i}\n`);
      await page.waitForFunction((r) => Number(document.body.dataset.drawn) > r, runs, { timeout: 20000 });
      times.push(performance.now() - t0);
      await new Promise((r) => setTimeout(r, 150));
    }
    times.sort((a, b) => a - b);
    console.log(JSON.stringify({ latency_ms: { min: times[0], median: times[n >> 1], max: times[n - 1] } }));
  } else {
    const paths = await page.locator("#view svg path").count();
    if (paths < 2) await fail(`expected the drawing's paths, found ${paths}`);
    const layers = await page.locator("#layers input[type=checkbox]").count();
    if (layers < 2) await fail(`expected layer toggles, found ${layers}`);

    // Edit: a new circle of radius 33 appears without a reload.
    const t0 = performance.now();
    fs.writeFileSync(script, original + "(draw (circle '(0 0) 33))\n");
    await drawn("A33 33");
    const latency = performance.now() - t0;
    if ((await page.evaluate(() => window.__marker)) !== 42) await fail("the page reloaded");

    // A layer toggle hides its group.
    await page.locator('#layers input[data-layer="AUX"]').uncheck();
    const display = await page.evaluate(() => [...document.querySelectorAll("#view svg > g")]
      .find((g) => g.getAttribute("inkscape:label") === "AUX").getAttribute("display"));
    if (display !== "none") await fail("unchecking AUX did not hide it");

    // The cursor's drawing coordinates: the centre of the circle is (0, 0).
    const box = await page.locator("#view").boundingBox();
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    const coords = await page.locator("#coords").textContent();
    if (!/^x -?\d+\.\d{3}  y -?\d+\.\d{3}$/.test(coords)) await fail(`coordinates shown: ${coords}`);

    // Break the script: the error shows, the last drawing stays.
    fs.writeFileSync(script, original + "(draw (circle '(0 0) 33))\n(draw (circle '(0 0) \"r\"))\n");
    await page.locator("#error").waitFor({ state: "visible", timeout: 20000 });
    const msg = await page.locator("#error").innerText();
    if (!msg.includes("bad argument type") || !msg.includes(":6:")) await fail(`error shown: ${msg}`);
    const still = await page.evaluate(() => document.querySelector("#view svg").innerHTML.includes("A33 33"));
    if (!still) await fail("the last good drawing was dropped");
    if ((await page.evaluate(() => window.__marker)) !== 42) await fail("the page reloaded");
    await page.screenshot({ path: shot });

    // Fixed again: the error goes away.
    fs.writeFileSync(script, original);
    await page.locator("#error").waitFor({ state: "hidden", timeout: 20000 });
    // A 3D drawing offers the orbit: Shift-drag re-renders it from another direction.
    fs.writeFileSync(script, "(draw (line '(0 0 0) '(10 0 0)))\n(draw (line '(0 0 0) '(0 0 10)))\n");
    await page.locator("#orbit").waitFor({ state: "visible", timeout: 20000 });
    await page.waitForFunction(() => document.body.dataset.drawn === document.body.dataset.runs);
    const plan = await page.evaluate(() => document.querySelector("#view svg").outerHTML);
    await page.keyboard.down("Shift");
    await page.mouse.move(box.x + 300, box.y + 300);
    await page.mouse.down();
    await page.mouse.move(box.x + 360, box.y + 260, { steps: 6 });
    await page.mouse.up();
    await page.keyboard.up("Shift");
    await page.waitForFunction((p) => document.querySelector("#view svg").outerHTML !== p, plan, { timeout: 20000 });
    if (errors.length) await fail("page errors: " + errors.join("; "));
    console.log(JSON.stringify({ ok: true, latency_ms: latency, paths, layers, coords, error: msg }));
  }
} catch (e) {
  await fail(String(e && e.stack || e));
}
await ctx.close();
fs.rmSync(profile, { recursive: true, force: true });
