// The screenshots of docs/atlas.md from a built site: the index sorted by H, a run page, the
// compare page with the first three runs of an ensemble at mid S (dark), an ensemble page.
// Usage: node atlas_screenshots.mjs SITE OUT_DIR RUN_SLUG ENSEMBLE_SLUG
import fs from "node:fs";
import path from "node:path";
import { pathToFileURL } from "node:url";
import puppeteer from "puppeteer-core";

const [site, out, runSlug, ensembleSlug] = process.argv.slice(2);
fs.mkdirSync(out, { recursive: true });
const browser = await puppeteer.launch({ executablePath: "/usr/bin/chromium", headless: true,
  args: ["--no-sandbox", "--disable-gpu"] });
const open = async (rel, theme = "light") => {
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 900 });
  await page.evaluateOnNewDocument((t) => localStorage.setItem("atlas-theme", t), theme);
  await page.goto(pathToFileURL(path.join(site, rel)).href, { waitUntil: "load" });
  return page;
};
const shot = async (page, name, height) => {
  await page.$$eval("img", (imgs) => imgs.forEach((i) => { i.loading = "eager"; }));
  await page.waitForFunction(() => Array.from(document.images).every((i) => i.complete), { timeout: 20000 });
  const full = await page.evaluate(() => document.documentElement.scrollHeight);
  await page.screenshot({ path: path.join(out, name), clip: { x: 0, y: 0, width: 1280, height: Math.min(full, height) },
    captureBeyondViewport: true });
};

let page = await open("index.html");
const th = await page.evaluateHandle(() => Array.from(document.querySelectorAll("#runs th")).find((c) => c.textContent === "H [h0]"));
await th.click(); await th.click();
await page.$eval(".scroll", (e) => { e.scrollLeft = 0; });
await shot(page, "index.png", 700);

page = await open(`runs/${runSlug}.html`);
await page.$eval("figure.player input[type=range]", (e) => { e.value = e.max; e.dispatchEvent(new Event("input")); });
await page.$$eval("figure.player", (figs) => figs.forEach((f) => {
  const r = f.querySelector("input[type=range]"); r.value = r.max; r.dispatchEvent(new Event("input")); }));
await new Promise((r) => setTimeout(r, 800));
await shot(page, "run.png", 2000);

page = await open("compare.html", "dark");
const members = await page.$$eval("#pick0 option", (o) => o.map((e) => e.value).filter((v) => v.includes("members")));
for (const [k, slug] of members.slice(0, 3).entries()) await page.select(`#pick${k}`, slug);
await page.waitForFunction(() => document.querySelectorAll("#panels img").length >= 3);
await page.$eval("#slider", (e) => { e.value = Math.round(+e.max / 2); e.dispatchEvent(new Event("input")); });
await new Promise((r) => setTimeout(r, 800));
await shot(page, "compare.png", 1500);

page = await open(`groups/${ensembleSlug}.html`);
await new Promise((r) => setTimeout(r, 500));
await shot(page, "ensemble.png", 2200);
await browser.close();
console.log("screenshots in " + out);
