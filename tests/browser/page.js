// page.js: loftplot -i's page in headless Chromium, driven by real mouse
// events through puppeteer-core (issue 27).  Run by tests/browser/run.sh
// from the top of the tree, with the module at node_modules of $NODE_DIR:
//
//   node tests/browser/page.js check DIR   the tests: a line "ok ..." or
//                                          "FAIL ..." each
//   node tests/browser/page.js bench DIR   ms per drag of 1 knot of 100
//   node tests/browser/page.js shot DIR    DIR/page.png: the insole's page
//                                          after a drag, for the README
//
// The references are outside the page: splinefit and patchdrag run as
// commands on what the page saved, and the mouse's own displacement.
"use strict";
const fs = require("fs");
const path = require("path");
const { execFileSync } = require("child_process");
const puppeteer = require(path.join(process.env.NODE_DIR,
  "node_modules", "puppeteer-core"));

const mode = process.argv[2], dir = path.resolve(process.argv[3]);
const B = process.env.B || "bin";
let failed = 0;
function ok(what) { console.log("ok " + what); }
function no(what) { console.log("FAIL " + what); failed++; }
function check(cond, what) { (cond ? ok : no)(what); }
function sh(prog, args, input) {
  return execFileSync(path.join(B, prog), args,
    { input: input, encoding: "utf8", stdio: ["pipe", "pipe", "pipe"] });
}
function rows(text) {
  return text.split("\n").filter(l => /^[-+0-9.]/.test(l))
    .map(l => l.trim().split(/\s+/).map(Number));
}

async function open(browser, file, requests) {
  const page = await browser.newPage();
  await page.setViewport({ width: 1200, height: 800 });
  page.on("request", r => requests.push(r.url()));
  const cdp = await page.target().createCDPSession();
  await cdp.send("Browser.setDownloadBehavior",
    { behavior: "allow", downloadPath: dir });
  await page.goto("file://" + file);
  // no time limit: a busy machine must not fail the test
  await page.waitForFunction("window.loftPage && window.loftPage.ready",
    { timeout: 0 });
  return page;
}

// a drag by the real mouse, in steps, from (x, y) by (dx, dy) pixels
async function drag(page, x, y, dx, dy) {
  await page.mouse.move(x, y);
  await page.mouse.down();
  for (let i = 1; i <= 5; i++)
    await page.mouse.move(x + dx * i / 5, y + dy * i / 5);
  await page.mouse.up();
}

async function waitFile(name) {
  const f = path.join(dir, name);
  for (let i = 0; i < 100 && !fs.existsSync(f); i++)
    await new Promise(r => setTimeout(r, 50));
  return fs.existsSync(f) ? fs.readFileSync(f, "utf8") : null;
}

async function curves(browser) {
  const knots = fs.readFileSync("man/figures/insole.knots", "utf8");
  const html = path.join(dir, "insole.html"), requests = [];
  fs.writeFileSync(html, execFileSync(path.join(B, "loftplot"),
    ["-i", "-c", "-K", "man/figures/insole.knots"],
    { input: sh("splinefit", [], knots) }));
  const page = await open(browser, html, requests);
  const K = 7;                   // knot 8, (180, -44): 0-based 7
  const at = await page.evaluate(k => {
    const r = document.querySelector(`[data-k="0"][data-i="${k}"]`)
      .getBoundingClientRect();
    return { x: r.x + r.width / 2, y: r.y + r.height / 2,
      a: document.getElementById("draw").getScreenCTM().a,
      step: window.loftPage.S.step, frame: window.loftPage.S.frame };
  }, K);
  const dx = 40, dy = -30;
  await drag(page, at.x, at.y, dx, dy);
  // the Manning method, open with a start tangent, a corner at knot 3
  await page.select("#method", "manning");
  await page.click("#closed");
  await page.type("#start", "1,-1");
  await page.keyboard.press("Tab");
  await page.click(`[data-k="0"][data-i="2"]`);
  await page.keyboard.press("c");
  await page.click("#save");
  const saved = await waitFile("edited.knots");
  const text = await page.evaluate(() =>
    document.getElementById("saved").value);
  const curve = await page.evaluate(() => window.loftPage.curve(0));
  const fig = await page.evaluate(() =>
    document.getElementById("figures").textContent);
  check(saved !== null && saved === text,
    "Save downloads edited.knots, the text it shows");
  if (saved === null) return requests;
  const want = rows(knots), got = rows(saved);
  // the knot moved with the mouse: 40 and 30 pixels of the picture's
  // scale, to the step the page rounds to (a thousandth of the frame
  // at most)
  const ex = want[K][0] + dx / at.a, ey = want[K][1] - dy / at.a;
  check(at.step <= Math.max(at.frame[2], at.frame[3]) / 1000 &&
    got.length === want.length &&
    Math.abs(got[K][0] - ex) <= at.step / 2 + 1e-9 &&
    Math.abs(got[K][1] - ey) <= at.step / 2 + 1e-9,
    `the dragged knot is at (${got[K]}), want (${ex}, ${ey}) within ` +
    `${at.step / 2}`);
  check(got.every((r, i) => i === K ||
    (r[0] === want[i][0] && r[1] === want[i][1])),
    "every other knot is saved as it was");
  const head = saved.split("\n")[0];
  check(/^points /.test(head) && / closed=0/.test(head) &&
    / method=manning/.test(head) && / start=1,-1/.test(head) &&
    / corners=3(\s|$)/.test(head),
    `the record says its options: '${head}'`);
  // splinefit of the saved record, as the page says to run it
  const cmd = await page.evaluate(() =>
    document.getElementById("cmd").textContent);
  check(/: splinefit edited\.knots$/.test(cmd),
    `the page gives the command: '${cmd}'`);
  const ref = sh("splinefit", [], saved);
  check(ref === curve && ref.length > 100,
    "splinefit of the saved knots is the page's curve, byte for byte");
  const line = execFileSync("sh", ["-c", `${B}/splinefit -v ` +
    `<'${path.join(dir, "edited.knots")}' 2>&1 >/dev/null`],
    { encoding: "utf8" });
  const energy = /bending energy ([^,]*)/.exec(line);
  check(energy && fig.indexOf("bending energy " + energy[1]) >= 0 &&
    /(\d+) inflexion/.exec(line) &&
    fig.indexOf(/(\d+) inflexion/.exec(line)[0]) >= 0,
    `the figures are splinefit -v's: '${line.trim()}' in '${fig}'`);
  // a knot added by a double-click halfway between knots 12 and 13,
  // then deleted: the record is the saved one again
  const mid = await page.evaluate(() => {
    const a = document.querySelector('[data-k="0"][data-i="11"]')
      .getBoundingClientRect();
    const b = document.querySelector('[data-k="0"][data-i="12"]')
      .getBoundingClientRect();
    return { x: (a.x + b.x + a.width) / 2, y: (a.y + b.y + a.height) / 2 };
  });
  await page.mouse.click(mid.x, mid.y, { clickCount: 2 });
  const added = await page.evaluate(() => window.loftPage.saved().knots);
  await page.keyboard.press("Delete");
  const deleted = await page.evaluate(() => window.loftPage.saved().knots);
  const ra = rows(added);
  check(ra.length === 23 && ra[12][0] > Math.min(want[11][0], want[12][0]) &&
    ra[12][0] < Math.max(want[11][0], want[12][0]) && / corners=3(\s|$)/.test(
      added.split("\n")[0]),
    `a double-click between knots 12 and 13 adds knot 13: ${ra[12]}`);
  check(deleted === saved, "Delete takes it out again");
  await page.close();
  return requests;
}

async function surfaces(browser) {
  const html = path.join(dir, "hull.html"), requests = [];
  fs.writeFileSync(html, execFileSync(path.join(B, "loftplot"),
    ["-i", "-v", "iso", "man/examples/hull.design"]));
  const page = await open(browser, html, requests);
  // the middle of the second patch, on the screen
  const at = await page.evaluate(() => {
    const S = window.loftPage.S, svg = document.getElementById("draw");
    const g = S.grid.filter(g => g[0] === 1 && g[1] === 0.5 &&
      g[2] === 0.5)[0];
    const x = g[3], y = g[4], z = g[5];
    const q = [(y - x) / Math.SQRT2, (2 * z - x - y) / Math.sqrt(6)];
    const p = new DOMPoint(q[0], -q[1]).matrixTransform(svg.getScreenCTM());
    return { x: p.x, y: p.y, a: svg.getScreenCTM().a };
  });
  const before = fs.readFileSync("man/examples/hull.design", "utf8");
  await drag(page, at.x, at.y, 30, -25);
  const last = await page.evaluate(() => window.loftPage.S.last);
  const design = await page.evaluate(() => window.loftPage.saved().design);
  await page.click("#save");
  const saved = await waitFile("edited.design");
  check(saved === design, "Save downloads edited.design, the design shown");
  check(last && last.args[0] === "patchdrag" && last.rc === 0,
    "the drag ran patchdrag");
  if (!last) return requests;
  const a = last.args.slice(1), w = a[a.indexOf("-w") + 1];
  const b = a[a.indexOf("-b") + 1].split(",").map(Number);
  // the displacement is the mouse's, in the oblique view's plane
  const px = (b[1] - b[0]) / Math.SQRT2 * at.a;
  const py = -(2 * b[2] - b[0] - b[1]) / Math.sqrt(6) * at.a;
  check(w === "1,1,1" && Math.abs(px - 30) < 1e-6 && Math.abs(py + 25) < 1e-6,
    `patchdrag ${a.join(" ")}: the mouse moved (30, -25), this (${px}, ${py})`);
  check(a.indexOf("-i") >= 0 && a[a.indexOf("-i") + 1] === "2" &&
    a[a.indexOf("-u") + 1] === "0.5" && a[a.indexOf("-v") + 1] === "0.5",
    "the point dragged is (0.5, 0.5) of patch id=2");
  const ref = sh("patchdrag", a, before);
  check(ref === saved && ref !== before,
    "patchdrag -w of the same drag is the saved design, byte for byte");
  await page.close();
  return requests;
}

// the insole at 1e12 units: loftplot writes its lengths in units of the
// svg's data-unit there, and the page's knots must sit on the curve and
// move with the mouse in the plane's own units
async function scaled(browser) {
  const knots = rows(fs.readFileSync("man/figures/insole.knots", "utf8"))
    .map(r => r.map(x => x * 1e12).join(" ")).join("\n") + "\n";
  const kf = path.join(dir, "big.knots"), html = path.join(dir, "big.html");
  fs.writeFileSync(kf, knots);
  const fitted = sh("splinefit", [], knots);
  const u = /<svg[^>]* data-unit="([^"]*)"/.exec(sh("loftplot", ["-c"], fitted));
  const unit = u ? Number(u[1]) : 1;
  check(unit !== 1, `loftplot names a data-unit at 1e12: ${unit}`);
  fs.writeFileSync(html, execFileSync(path.join(B, "loftplot"),
    ["-i", "-c", "-K", kf], { input: fitted }));
  const page = await open(browser, html, []);
  const K = 7, want = rows(knots);
  const at = await page.evaluate(k => {
    const r = document.querySelector(`[data-k="0"][data-i="${k}"]`)
      .getBoundingClientRect(), m = document.getElementById("draw")
      .getScreenCTM();
    return { x: r.x + r.width / 2, y: r.y + r.height / 2, a: m.a, e: m.e,
      f: m.f, step: window.loftPage.S.step };
  }, K);
  // the knot drawn where the plane point (x, y) is: the screen point
  // (e + a x / unit, f - a y / unit), within a pixel
  const sx = at.e + at.a * want[K][0] / unit, sy = at.f - at.a * want[K][1] / unit;
  check(Math.abs(at.x - sx) <= 1 && Math.abs(at.y - sy) <= 1,
    `at 1e12 the knot is drawn at (${at.x}, ${at.y}), want (${sx}, ${sy})`);
  const dx = 40, dy = -30;
  await drag(page, at.x, at.y, dx, dy);
  const got = rows(await page.evaluate(() => window.loftPage.saved().knots));
  const ex = want[K][0] + dx * unit / at.a, ey = want[K][1] - dy * unit / at.a;
  check(got.length === want.length &&
    Math.abs(got[K][0] - ex) <= at.step / 2 + 1e-9 * Math.abs(ex) &&
    Math.abs(got[K][1] - ey) <= at.step / 2 + 1e-9 * Math.abs(ey),
    `at 1e12 the dragged knot is at (${got[K]}), want (${ex}, ${ey}) ` +
    `within ${at.step / 2}`);
  await page.close();
}

async function shot(browser) {
  const html = path.join(dir, "shot.html");
  fs.writeFileSync(html, execFileSync(path.join(B, "loftplot"),
    ["-i", "-c", "-K", "man/figures/insole.knots"],
    { input: sh("splinefit", ["-m", "manning"], fs.readFileSync(
      "man/figures/insole.knots", "utf8")) }));
  const page = await open(browser, html, []);
  await page.setViewport({ width: 1100, height: 600 });
  await page.click("#frame");
  await page.select("#method", "manning");
  const at = await page.evaluate(() => {
    const r = document.querySelector('[data-k="0"][data-i="17"]')
      .getBoundingClientRect();
    return { x: r.x + r.width / 2, y: r.y + r.height / 2 };
  });
  await drag(page, at.x, at.y, 0, -25);
  await page.screenshot({ path: path.join(dir, "page.png") });
}

async function bench(browser) {
  // 100 knots on a wavy oval, as a designer's outline might have
  const k = [];
  for (let i = 0; i < 100; i++) {
    const t = 2 * Math.PI * i / 100, r = 100 + 10 * Math.sin(5 * t);
    k.push((r * Math.cos(t)).toFixed(3) + " " + (0.7 * r * Math.sin(t)).toFixed(3));
  }
  const knots = k.join("\n") + "\n", kf = path.join(dir, "k100.knots");
  fs.writeFileSync(kf, knots);
  const html = path.join(dir, "k100.html");
  fs.writeFileSync(html, execFileSync(path.join(B, "loftplot"),
    ["-i", "-c", "-K", kf], { input: sh("splinefit", [], knots) }));
  const page = await open(browser, html, []);
  const t = await page.evaluate(() => window.loftPage.bench(200));
  t.sort((x, y) => x - y);
  const mean = t.reduce((s, x) => s + x, 0) / t.length;
  const size = fs.statSync(path.join(B, "wasm", "loft.wasm")).size;
  console.log(`page: module ${size} bytes; a drag of 1 knot of 100 with ` +
    `the comb (splinefit and loftplot in the module, and the DOM): ` +
    `median ${t[t.length >> 1].toFixed(2)} ms, mean ${mean.toFixed(2)} ms, ` +
    `90th percentile ${t[Math.floor(t.length * 0.9)].toFixed(2)} ms ` +
    `over ${t.length} drags`);
}

(async () => {
  const browser = await puppeteer.launch({
    executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
    headless: true, args: ["--no-sandbox", "--disable-gpu"] });
  try {
    if (mode === "bench") {
      await bench(browser);
    } else if (mode === "shot") {
      await shot(browser);
    } else {
      const req = (await curves(browser)).concat(await surfaces(browser));
      await scaled(browser);
      const far = req.filter(u => !/^(file|data|blob):/.test(u) ||
        (/^file:/.test(u) && !/\.html$/.test(u)));
      check(req.length >= 2 && far.length === 0,
        `the pages ask for nothing but themselves: ${far.join(" ") || "none"}`);
    }
  } catch (e) {
    no("the browser run: " + (e && e.stack || e));
  }
  await browser.close();
  process.exit(failed ? 1 : 0);
})();
