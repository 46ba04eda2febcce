// Opens reports that the real binary writes (a run's, an eval's and a bench's) in headless Chromium (Debian's
// chromium, driven by puppeteer-core pinned in web/package-lock.json) and
// checks what a person would see: the page loads without console errors,
// every plot and the 3D canvas draw coloured pixels, and the trajectory plot
// spans the trajectory. Exit 77 (ctest: skipped) only when chromium is absent.
//
// node report_page_test.mjs --lvslam BIN --node-modules DIR [--work DIR] [--screenshots DIR]
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { createRequire } from 'node:module';

const args = Object.fromEntries(process.argv.slice(2).reduce((pairs, a, i, all) =>
  (a.startsWith('--') ? [...pairs, [a.slice(2), all[i + 1]]] : pairs), []));
const chromium = ['/usr/bin/chromium', '/usr/bin/chromium-browser'].find((p) => fs.existsSync(p));
if (!chromium) {
  console.log('SKIPPED: chromium is not installed (scripts/install-deps.sh installs it)');
  process.exit(77);
}
const require = createRequire(path.join(args['node-modules'], 'noop.js'));
let puppeteer;
try {
  puppeteer = require('puppeteer-core');
} catch (error) {
  console.error(`puppeteer-core not found under ${args['node-modules']}: run scripts/install-deps.sh (npm ci in web/)`);
  process.exit(1);
}

const work = args.work || fs.mkdtempSync(path.join(os.tmpdir(), 'lvslam_report_'));
const lvslam = (...a) => execFileSync(args.lvslam, a, { cwd: work, encoding: 'utf8' });
let failed = 0, passed = 0;
const check = (ok, what) => { ok ? ++passed : ++failed; console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`); };

// A short simulated room: ground truth, both subsystems, a map and lines.
if (!fs.existsSync(path.join(work, 'run', 'report.html'))) {
  lvslam('simulate', '--scenario', 'room', '--duration', '8', '--out', 'seq');
  lvslam('run', '--sequence', 'seq', '--out', 'run');
}
lvslam('eval', '--gt', 'run/groundtruth.tum', '--est', 'run/trajectory.tum', '--report', 'eval.html');
// bench.html of the smallest families suite (three short runs of the room).
if (!fs.existsSync(path.join(work, 'bench', 'bench.html')))
  lvslam('bench', '--suite', 'families', '--families', 'room', '--quick', '--duration', '3', '--no-ablations',
    '--work-dir', 'bench', '--no-doc');

function readTum(file) {
  return fs.readFileSync(file, 'utf8').split('\n').filter((l) => l.trim() && !l.startsWith('#'))
    .map((l) => l.trim().split(/\s+/).map(Number));
}

// Pixels of each canvas that are clearly coloured (not white, grey or black:
// axes and labels are grey, data is drawn in colour).
async function colouredPixels(page) {
  return page.evaluate(() => Array.from(document.querySelectorAll('canvas')).map((canvas) => {
    const copy = document.createElement('canvas');
    copy.width = canvas.width; copy.height = canvas.height;
    const ctx = copy.getContext('2d');
    ctx.drawImage(canvas, 0, 0);
    const px = ctx.getImageData(0, 0, copy.width, copy.height).data;
    let coloured = 0;
    for (let i = 0; i < px.length; i += 4) {
      const [r, g, b, a] = [px[i], px[i + 1], px[i + 2], px[i + 3]];
      if (a > 0 && Math.max(Math.abs(r - g), Math.abs(g - b), Math.abs(r - b)) > 60) ++coloured;
    }
    return { id: canvas.id, width: canvas.width, height: canvas.height, coloured };
  }));
}

// The trajectory plot's axes and the plotted online estimate (the dataset
// after the ground truth's), by axis name.
async function trajectoryPlot(page) {
  return page.evaluate(() => {
    const chart = window.lvslamReport.charts['traj-top'];
    const est = chart.data.datasets[1];
    const range = (values) => [Math.min(...values), Math.max(...values)];
    return {
      axes: [chart.options.scales.x.title.text[0], chart.options.scales.y.title.text[0]],
      scale: [[chart.scales.x.min, chart.scales.x.max], [chart.scales.y.min, chart.scales.y.max]],
      plotted: [range(est.data.map((q) => q.x)), range(est.data.map((q) => q.y))],
    };
  });
}

async function openReport(browser, file, expectedCanvases, withTrajectory = true) {
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 900 });
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('requestfailed', (r) => errors.push('request failed: ' + r.url()));
  const network = [];
  page.on('request', (r) => { if (!/^(file|blob|data):/.test(r.url())) network.push(r.url()); });
  await page.goto('file://' + path.resolve(work, file), { waitUntil: 'load' });
  const drawn = await page.evaluate(() => window.lvslamReport.ready.then(() => 'drawn', (e) => String(e)));
  check(drawn === 'drawn', `${file}: the page draws (${drawn})`);
  check(errors.length === 0, `${file}: no console errors${errors.length ? ': ' + errors.join(' | ') : ''}`);
  check(network.length === 0, `${file}: no network requests${network.length ? ': ' + network.join(' ') : ''}`);
  const canvases = await colouredPixels(page);
  for (const id of expectedCanvases) check(canvases.some((c) => c.id === id), `${file}: has canvas ${id}`);
  for (const c of canvases) check(c.coloured > 50, `${file}: ${c.id} (${c.width}x${c.height}) draws coloured pixels (${c.coloured})`);
  if (withTrajectory) await checkTrajectoryPlot(page, file);
  if (args.screenshots) {  // one PNG per section, for docs/
    fs.mkdirSync(args.screenshots, { recursive: true });
    const sections = await page.$$('section');
    for (const [i, sec] of sections.entries())
      await sec.screenshot({ path: path.join(args.screenshots, `${path.basename(file, '.html')}-${i}.png`) });
  }
  await page.close();
}

// The trajectory plot spans the ground truth, as the run wrote it.
async function checkTrajectoryPlot(page, file) {
  const plot = await trajectoryPlot(page).catch(() => ({ axes: [] }));
  check(plot.axes.length === 2, `${file}: has a trajectory plot with two axes`);
  const gt = readTum(path.join(work, 'run', 'groundtruth.tum'));
  plot.axes.forEach((name, k) => {
    const column = 1 + 'xyz'.indexOf(name);
    const values = gt.map((row) => row[column]);
    const [lo, hi] = [Math.min(...values), Math.max(...values)];
    const [plo, phi] = plot.plotted[k], [slo, shi] = plot.scale[k];
    check(Math.abs(plo - lo) < 0.1 && Math.abs(phi - hi) < 0.1,
      `${file}: plotted ${name} extent [${plo.toFixed(3)}, ${phi.toFixed(3)}] matches the ground truth's [${lo.toFixed(3)}, ${hi.toFixed(3)}]`);
    check(slo <= lo && shi >= hi && shi - slo < 2 * Math.max(hi - lo, 1) + 1,
      `${file}: the ${name} axis [${slo.toFixed(3)}, ${shi.toFixed(3)}] frames it`);
  });
}

const browser = await puppeteer.launch({
  executablePath: chromium, headless: true,
  // No GPU on a VM: WebGL through SwiftShader, Chromium's software renderer;
  // the plots' 2D canvases on the CPU (through SwiftShader they take seconds).
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-gpu-sandbox',
    '--disable-accelerated-2d-canvas'],
});
try {
  await openReport(browser, 'run/report.html', ['traj-top', 'traj-side', 'err-ate', 'det-source', 'det-tracking',
    'fus-lines', 'fus-classes', 'time-frame', 'time-scan', 'time-latency', 'view3d-canvas']);
  await openReport(browser, 'eval.html', ['traj-top', 'traj-side', 'err-ate']);
  await openReport(browser, 'bench/bench.html', ['bench-0'], false);
} finally {
  await browser.close();
}
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
