// Opens an atlas site in headless Chromium (Debian's, through puppeteer-core) and checks it as
// a user would see it: every page without console errors or missing files, every image and
// animation frame drawn (not blank), the runs table sorts and filters, the compare page picks
// runs from its menus and plays them in step, the dark theme and a phone-sized screen.
// Usage: node atlas_browser.mjs SITE SHOTS_DIR [CHROMIUM]; exit 0 when every check passes.
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";
import puppeteer from "puppeteer-core";

const [site, shots, chromium = "/usr/bin/chromium"] = process.argv.slice(2);
fs.mkdirSync(shots, { recursive: true });
const failures = [];
const fail = (msg) => { failures.push(msg); console.log("FAIL " + msg); };
const url = (rel) => pathToFileURL(path.join(site, rel)).href;

const browser = await puppeteer.launch({
  executablePath: chromium, headless: true,
  args: ["--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--no-first-run"],
});
// A blank page that measures screenshots: a data: image never taints its canvas.
const meter = await browser.newPage();
async function spread(png) {
  return meter.evaluate(async (b64) => {
    const img = new Image();
    img.src = "data:image/png;base64," + b64;
    await img.decode();
    const c = document.createElement("canvas");
    c.width = img.width; c.height = img.height;
    const ctx = c.getContext("2d");
    ctx.drawImage(img, 0, 0);
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    let n = 0, s = 0, s2 = 0;
    for (let i = 0; i < d.length; i += 16) { const y = (d[i] + d[i + 1] + d[i + 2]) / 3; n++; s += y; s2 += y * y; }
    return Math.sqrt(Math.max(0, s2 / n - (s / n) ** 2));
  }, png);
}
async function notBlank(handle, what) {
  const box = await handle.boundingBox();
  if (!box || box.width < 8 || box.height < 8) return fail(`${what}: not displayed (box ${JSON.stringify(box)})`);
  const sd = await spread(await handle.screenshot({ encoding: "base64" }));
  if (sd < 3) fail(`${what}: blank (luminance spread ${sd.toFixed(2)})`);
}

async function open(rel, viewport = { width: 1280, height: 900 }) {
  const page = await browser.newPage();
  await page.setViewport(viewport);
  page.on("console", (m) => { if (m.type() === "error") fail(`${rel}: console error: ${m.text()}`); });
  page.on("pageerror", (e) => fail(`${rel}: page error: ${e.message}`));
  page.on("requestfailed", (r) => fail(`${rel}: request failed: ${r.url()} (${r.failure()?.errorText})`));
  await page.goto(url(rel), { waitUntil: "load" });
  return page;
}

// Every link and source of the page names a file that exists (and nothing off this disc).
async function checkLinks(page, rel) {
  const refs = await page.evaluate(() => Array.from(document.querySelectorAll("a[href], img[src], script[src], link[href]"))
    .map((e) => e.href || e.src));
  for (const ref of refs) {
    const u = new URL(ref);
    if (u.protocol !== "file:") { fail(`${rel}: link off the disc: ${ref}`); continue; }
    const file = fileURLToPath(ref.split("#")[0].split("?")[0]);
    if (!fs.existsSync(file)) fail(`${rel}: broken link ${ref}`);
  }
  return refs.length;
}

// Every image loaded (lazy ones scrolled to first) and drawn.
async function checkImages(page, rel) {
  const imgs = await page.$$("img");
  for (const [i, img] of imgs.entries()) {
    await img.scrollIntoView();
    const ok = await img.evaluate(async (e) => { try { await e.decode(); } catch (x) { /* checked below */ }
      return e.complete && e.naturalWidth > 0; });
    const src = await img.evaluate((e) => e.getAttribute("src"));
    if (!ok) { fail(`${rel}: image ${src} not loaded`); continue; }
    await notBlank(img, `${rel}: image ${i} ${src}`);
  }
  return imgs.length;
}

const pages = ["index.html", "compare.html"]
  .concat(fs.readdirSync(path.join(site, "runs")).filter((f) => f.endsWith(".html")).map((f) => "runs/" + f))
  .concat(fs.existsSync(path.join(site, "groups"))
    ? fs.readdirSync(path.join(site, "groups")).filter((f) => f.endsWith(".html")).map((f) => "groups/" + f) : []);
const report = { pages: {} };
for (const rel of pages) {
  const page = await open(rel);
  const links = await checkLinks(page, rel);
  const images = await checkImages(page, rel);
  const plots = await page.$$(".plot canvas");
  for (const [i, c] of plots.entries()) { await c.scrollIntoView(); await notBlank(c, `${rel}: plot ${i}`); }
  report.pages[rel] = { links, images, plots: plots.length };
  if (rel.startsWith("runs/") && rel === pages.find((p) => p.startsWith("runs/"))) {
    if (!plots.length) fail(`${rel}: no series plots`);
    await page.screenshot({ path: path.join(shots, "run.png"), fullPage: true });
  }
  if (rel.startsWith("groups/")) await page.screenshot({ path: path.join(shots, "group_" + path.basename(rel, ".html") + ".png"), fullPage: true });
  await page.close();
}

// The index: sort by a numeric column both ways, and filter.
{
  const page = await open("index.html");
  const column = async (name) => page.evaluate((name) => {
    const t = document.getElementById("runs");
    const i = Array.from(t.tHead.rows[0].cells).findIndex((c) => c.textContent.replace(/[▲▼]/g, "").trim() === name);
    return Array.from(t.tBodies[0].rows).filter((r) => !r.hidden).map((r) => r.cells[i].textContent.trim());
  }, name);
  const header = (name) => page.evaluateHandle((name) => Array.from(document.querySelectorAll("#runs thead th"))
      .find((c) => c.textContent.trim() === name), name);
  for (const name of ["H [h0]", "run"]) {
    const th = await header(name);
    if (!(await th.evaluate((e) => !!e))) { fail(`index: no column ${name}`); continue; }
    await th.click();
    const up = await column(name);
    await th.click();
    const down = await column(name);
    up.splice(up.indexOf("") >= 0 ? up.indexOf("") : up.length);  // empty cells last either way
    down.splice(down.indexOf("") >= 0 ? down.indexOf("") : down.length);
    const key = (v) => (name === "run" ? v.toLowerCase() : parseFloat(v));
    const sorted = (a, dir) => a.every((v, i) => i === 0 || (key(a[i - 1]) <= key(v)) === (dir > 0) || key(a[i - 1]) === key(v));
    if (up.length < 2 || !sorted(up, 1) || !sorted(down, -1)) fail(`index: column ${name} does not sort: ${up} / ${down}`);
    report["sorted_" + name] = [up, down];
  }
  const all = (await column("run")).length;
  await page.type("#filter", "seed2");
  const some = await column("run");
  if (!(some.length >= 1 && some.length < all && some.every((v) => v.includes("seed2")))) fail(`index: filter gives ${some}`);
  await page.$eval("#filter", (e) => { e.value = ""; e.dispatchEvent(new Event("input")); });
  await page.screenshot({ path: path.join(shots, "index.png"), fullPage: true });
  // The dark theme, kept across pages.
  await page.click("#theme");
  const theme = await page.evaluate(() => document.documentElement.dataset.theme);
  await page.screenshot({ path: path.join(shots, "index_" + theme + ".png"), fullPage: true });
  await page.click("#theme");
  await page.close();
}

// The compare page: pick three runs from the menus, play, and see every panel move with S.
{
  const page = await open("compare.html");
  const options = await page.$$eval("#pick0 option", (o) => o.map((e) => e.value).filter(Boolean));
  const chosen = options.filter((v) => /seed/.test(v)).slice(0, 3);
  if (chosen.length < 2) fail(`compare: too few runs in the menus: ${options}`);
  for (const [k, slug] of chosen.entries()) await page.select(`#pick${k}`, slug);
  await page.waitForFunction((n) => document.querySelectorAll("#panels img").length === n &&
    Array.from(document.querySelectorAll("#panels img")).every((i) => i.complete && i.naturalWidth > 0),
  { timeout: 10000 }, chosen.length);
  const state = () => page.evaluate(() => ({
    value: +document.getElementById("slider").value, max: +document.getElementById("slider").max,
    at: document.getElementById("at").textContent,
    srcs: Array.from(document.querySelectorAll("#panels img")).map((i) => i.getAttribute("src")),
  }));
  const before = await state();
  await page.click("#play");
  await page.waitForFunction(() => +document.getElementById("slider").value >= +document.getElementById("slider").max,
    { timeout: 15000 });
  await page.waitForFunction(() => Array.from(document.querySelectorAll("#panels img")).every((i) => i.complete));
  const after = await state();
  if (!(before.max > 0 && after.value === after.max)) fail(`compare: play did not reach the end: ${JSON.stringify(after)}`);
  if (after.srcs.some((s, i) => s === before.srcs[i])) fail(`compare: a panel did not move: ${before.srcs} -> ${after.srcs}`);
  // In step: members of one ensemble share their output times, so every panel shows the same frame number.
  const frame = (s) => s.match(/frame_(\d+)/)[1];
  if (new Set(after.srcs.map(frame)).size !== 1) fail(`compare: panels out of step: ${after.srcs}`);
  for (const [i, img] of (await page.$$("#panels img")).entries()) await notBlank(img, `compare: panel ${i}`);
  const overlay = await page.$$("#overlay canvas");
  if (!overlay.length) fail("compare: no overlaid series");
  else await notBlank(overlay[0], "compare: overlay");
  const legend = await page.$$eval("#overlay .u-legend .u-series", (s) => s.length);
  if (legend !== chosen.length + 1) fail(`compare: overlay has ${legend - 1} series for ${chosen.length} runs`);
  // The slider half way: every panel at the frame of that S.
  await page.$eval("#slider", (e) => { e.value = Math.floor(+e.max / 2); e.dispatchEvent(new Event("input")); });
  const half = await state();
  if (new Set(half.srcs.map(frame)).size !== 1 || half.srcs.map(frame)[0] === frame(after.srcs[0]))
    fail(`compare: half way, panels out of step or not moved back: ${half.srcs}`);
  report.compare = { before, after, half };
  await page.screenshot({ path: path.join(shots, "compare.png"), fullPage: true });
  await page.close();
}

// A phone: the index and a run page fit the screen's width.
for (const rel of ["index.html", pages.find((p) => p.startsWith("runs/"))]) {
  const page = await open(rel, { width: 390, height: 844, isMobile: true, deviceScaleFactor: 1 });
  const over = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
  if (over > 1) fail(`${rel}: wider than a phone by ${over} px`);
  await page.screenshot({ path: path.join(shots, "phone_" + path.basename(rel, ".html") + ".png") });
  await page.close();
}

// Load time of a run page from disc.
{
  const page = await open(pages.find((p) => p.startsWith("runs/")));
  const t0 = Date.now();
  await page.reload({ waitUntil: "load" });
  report.run_page_load_ms = Date.now() - t0;
  if (report.run_page_load_ms > 1000) fail(`run page took ${report.run_page_load_ms} ms to load`);
  await page.close();
}

await browser.close();
fs.writeFileSync(path.join(shots, "report.json"), JSON.stringify({ failures, ...report }, null, 1));
console.log(`${pages.length} pages checked, ${failures.length} failures; screenshots in ${shots}`);
process.exit(failures.length ? 1 : 0);
