// Shared by every section of a report: the data, the page skeleton, and one
// way to make a Chart.js plot (no animation, no parsing: thousands of frames).
const DATA = JSON.parse(document.getElementById('lvslam-data').textContent);
// What a test (tests/report/report_page_test.mjs) reads back from the page.
const LV = (window.lvslamReport = { charts: {}, view3d: null, ready: null });
const COLOURS = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e', '#8c564b', '#e377c2', '#17becf'];
const SOURCE_COLOURS = { visual: '#1f77b4', lidar: '#ff7f0e', none: '#999999' };

function el(tag, attrs, ...children) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (k === 'text') node.textContent = v;
    else node.setAttribute(k, v);
  }
  for (const child of children) if (child != null) node.append(child);
  return node;
}

function section(title, note) {
  const s = el('section', {}, el('h2', { text: title }));
  if (note) s.append(el('p', { class: 'note', text: note }));
  document.getElementById('app').append(s);
  return s;
}

function fmtNum(v, digits) {
  if (v == null || !isFinite(v)) return '-';
  return Math.abs(v) >= 1e4 || (Math.abs(v) < 1e-3 && v !== 0) ? v.toExponential(2) : v.toFixed(digits);
}

function table(headers, rows) {
  const t = el('table', {}, el('tr', {}, ...headers.map((h) => el('th', { text: h }))));
  for (const row of rows) t.append(el('tr', {}, ...row.map((c) => el('td', { text: String(c) }))));
  return t;
}

// Points of one series: x and y arrays of equal length, nulls skipped.
function points(xs, ys) {
  const out = [];
  for (let i = 0; i < xs.length; ++i) if (ys[i] != null && xs[i] != null) out.push({ x: xs[i], y: ys[i] });
  return out;
}

function lineDataset(label, data, colour, extra) {
  return Object.assign({ label, data, borderColor: colour, backgroundColor: colour, borderWidth: 1.2,
    pointRadius: 0, showLine: true, fill: false }, extra || {});
}

// A plot needs no more points than it has pixels across: a 10-minute run has
// 9000 frames. Longer series are cut into equal runs of frames, each drawn as
// its extremes (min and max, so a spike stays) or, stacked, as its mean (the
// same frames in every series, so the stack still adds up).
const MAX_PLOT_POINTS = 2000;

function thinned(data, stacked) {
  if (data.length <= MAX_PLOT_POINTS) return data;
  const k = Math.ceil(data.length / (stacked ? MAX_PLOT_POINTS : MAX_PLOT_POINTS / 2));
  const out = [];
  for (let i = 0; i < data.length; i += k) {
    const run = data.slice(i, i + k);
    if (stacked) {
      out.push({ x: run[0].x, y: run.reduce((sum, q) => sum + q.y, 0) / run.length });
    } else {
      let lo = run[0], hi = run[0];
      for (const q of run) { if (q.y < lo.y) lo = q; if (q.y > hi.y) hi = q; }
      out.push(...(lo.x <= hi.x ? [lo, hi] : [hi, lo]));
    }
  }
  return out;
}

function makeChart(parent, id, title, datasets, options) {
  const canvas = el('canvas', { id });
  parent.append(el('div', { class: 'plot' }, el('h3', { text: title }), canvas));
  const o = options || {};
  if (o.type !== 'bar') for (const d of datasets) d.data = thinned(d.data, !!o.stacked);
  const chart = new Chart(canvas, {
    type: o.type || 'line',
    data: { datasets, labels: o.labels },
    options: {
      animation: false, parsing: o.parsing ?? false, normalized: true, responsive: true,
      aspectRatio: o.aspectRatio || 2.6,
      interaction: { mode: 'nearest', intersect: false },
      plugins: { legend: { labels: { boxWidth: 12 } }, tooltip: { enabled: true } },
      scales: o.scales || {
        x: { type: 'linear', title: { display: true, text: o.xTitle || 'time (s)' } },
        y: { stacked: !!o.stacked, beginAtZero: !!o.stacked, title: { display: true, text: o.yTitle || '' } },
      },
    },
  });
  LV.charts[id] = chart;
  return chart;
}

// Seconds since the run's first stamp, so every plot shares its time axis.
const T0 = (() => {
  const stamps = [];
  if (DATA.stats && DATA.stats.frames.length) stamps.push(DATA.stats.frames[0].t);
  if (DATA.stats && DATA.stats.scans.length) stamps.push(DATA.stats.scans[0].t);
  for (const e of DATA.estimates || []) if (e.trajectory.t.length) stamps.push(e.trajectory.t[0]);
  return stamps.length ? Math.min(...stamps) : 0;
})();
const rel = (t) => t - T0;
