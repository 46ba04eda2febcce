// The trajectory from above and from the side, the ground truth beside it:
// each estimate moved into the ground truth's world by its own alignment (as
// its ATE is computed), coloured by ATE or by the subsystem in use.

// p' = s R p + t of the estimate's alignment; the identity without ground truth.
function alignedPositions(entry) {
  const p = entry.trajectory.p;
  const e = entry.errors;
  if (!e) return p;
  const out = new Array(p.length);
  for (let i = 0; i < p.length; i += 3) {
    for (let r = 0; r < 3; ++r)
      out[i + r] = e.scale * (e.R[3 * r] * p[i] + e.R[3 * r + 1] * p[i + 1] + e.R[3 * r + 2] * p[i + 2]) + e.t[r];
  }
  return out;
}

// The vertical axis: the one along which the ground truth (else the online
// estimate) moves least, as a ground robot or a hand-held rig does.
function upAxis() {
  const p = DATA.groundtruth ? DATA.groundtruth.p : DATA.estimates[0].trajectory.p;
  const range = [0, 1, 2].map((a) => {
    let lo = Infinity, hi = -Infinity;
    for (let i = a; i < p.length; i += 3) { lo = Math.min(lo, p[i]); hi = Math.max(hi, p[i]); }
    return hi - lo;
  });
  return p.length ? range.indexOf(Math.min(...range)) : 2;
}

// For each pose of an estimate, its ATE (null when not associated).
function ateAtPoses(entry) {
  const t = entry.trajectory.t;
  const out = new Array(t.length).fill(null);
  if (!entry.errors) return out;
  const ate = entry.errors.series[0];
  let j = 0;
  for (let i = 0; i < ate.t.length; ++i) {
    while (j < t.length && t[j] < ate.t[i] - 1e-6) ++j;
    if (j < t.length) out[j] = ate.v[i];
  }
  return out;
}

// The subsystem whose pose the online output took at each pose's time.
function sourceAtPoses(entry) {
  const frames = DATA.stats ? DATA.stats.frames : [];
  const t = entry.trajectory.t;
  const out = [];
  let j = 0;
  for (let i = 0; i < t.length; ++i) {
    while (j + 1 < frames.length && frames[j + 1].t <= t[i] + 1e-6) ++j;
    out.push(frames.length ? (frames[j].pose ? frames[j].source : 'none') : 'none');
  }
  return out;
}

function errorColour(v, max) {
  if (v == null) return '#999999';
  const x = Math.max(0, Math.min(1, v / max));
  // blue (small) -> green -> red (the largest error of the run)
  const r = Math.round(255 * Math.min(1, 2 * x)), g = Math.round(200 * (1 - Math.abs(2 * x - 1))), b = Math.round(255 * Math.max(0, 1 - 2 * x));
  return `rgb(${r},${g},${b})`;
}

function equalRanges(datasets, ax, ay, pad) {
  let xlo = Infinity, xhi = -Infinity, ylo = Infinity, yhi = -Infinity;
  for (const d of datasets) for (const q of d.data) {
    xlo = Math.min(xlo, q.x); xhi = Math.max(xhi, q.x); ylo = Math.min(ylo, q.y); yhi = Math.max(yhi, q.y);
  }
  if (!isFinite(xlo)) [xlo, xhi, ylo, yhi] = [-1, 1, -1, 1];  // nothing to plot
  const half = Math.max(xhi - xlo, (yhi - ylo) * ax / ay, 0.5) / 2 * (1 + pad);
  const cx = (xlo + xhi) / 2, cy = (ylo + yhi) / 2;
  return { x: [cx - half, cx + half], y: [cy - half * ay / ax, cy + half * ay / ax] };
}

function trajectorySection() {
  const s = section('Trajectory', DATA.groundtruth
    ? 'Each estimate aligned onto the ground truth as its ATE is computed (alignment in the table below).'
    : 'No ground truth: the estimates as written.');
  const names = ['x', 'y', 'z'];
  const up = upAxis();
  const [h1, h2] = [0, 1, 2].filter((a) => a !== up);
  const controls = el('div', { class: 'controls' });
  const select = el('select', { id: 'traj-colour' },
    el('option', { value: 'estimate', text: 'one colour per trajectory' }),
    DATA.groundtruth ? el('option', { value: 'error', text: 'ATE (blue small, red largest)' }) : null,
    DATA.stats ? el('option', { value: 'source', text: 'subsystem in use (blue visual, orange LiDAR, grey none)' }) : null);
  controls.append(el('label', { text: 'colour by ' }), select);
  s.append(controls);
  const row = el('div', { class: 'row' });
  s.append(row);
  // Every k-th pose (and the last) when there are more than a plot shows.
  const shown = (n) => {
    const k = Math.max(1, Math.ceil(n / MAX_PLOT_POINTS)), idx = [];
    for (let i = 0; i < n; i += k) idx.push(i);
    if (n && idx[idx.length - 1] !== n - 1) idx.push(n - 1);
    return idx;
  };
  const estimates = DATA.estimates.map((e) => {
    const idx = shown(e.trajectory.t.length), p = alignedPositions(e), ate = ateAtPoses(e), source = sourceAtPoses(e);
    return { entry: e, idx, p, ate: idx.map((i) => ate[i]), source: idx.map((i) => source[i]) };
  });
  const maxAte = Math.max(1e-9, ...estimates.flatMap((e) => e.ate.filter((v) => v != null)));
  // From above at equal scale, as wide as the ground covered (a corridor is long).
  const span = (p, a) => { let lo = Infinity, hi = -Infinity; for (let i = a; i < p.length; i += 3) { lo = Math.min(lo, p[i]); hi = Math.max(hi, p[i]); } return hi - lo; };
  const ref = DATA.groundtruth ? DATA.groundtruth.p : estimates[0].p;
  const topAspect = Math.max(0.8, Math.min(4, span(ref, h1) / Math.max(span(ref, h2), 1e-6))) || 1;
  // Beside the top view, or below it at its width when that one is wide.
  const views = [['traj-top', 'From above', h1, h2, topAspect], ['traj-side', 'From the side', h1, up, topAspect > 1.6 ? 4 : 2]];
  const charts = views.map(([id, title, ax, ay, aspect]) => {
    const top = id === 'traj-top';
    const datasets = [];
    if (DATA.groundtruth) {
      const g = DATA.groundtruth.p;
      datasets.push(lineDataset(DATA.groundtruth.name, shown(DATA.groundtruth.t.length).map((i) => ({ x: g[3 * i + ax], y: g[3 * i + ay] })), '#444444', { borderDash: [4, 3] }));
    }
    estimates.forEach((e, k) => {
      datasets.push(lineDataset(e.entry.trajectory.name, e.idx.map((i) => ({ x: e.p[3 * i + ax], y: e.p[3 * i + ay] })), COLOURS[k % COLOURS.length]));
    });
    const r = equalRanges(datasets, top ? aspect : 1, top ? 1 : 0.25, 0.06);
    const scales = {
      x: { type: 'linear', min: r.x[0], max: r.x[1], title: { display: true, text: names[ax] + ' (m)' } },
      y: { type: 'linear', min: top ? r.y[0] : undefined, max: top ? r.y[1] : undefined,
        title: { display: true, text: names[ay] + ' (m)' } },
    };
    const div = el('div', { class: !top ? 'col-wide' : aspect > 1.6 ? 'col-full' : 'col-square' });
    row.append(div);
    return makeChart(div, id, title, datasets, { scales, aspectRatio: aspect });
  });
  const recolour = () => {
    const mode = select.value;
    for (const chart of charts) {
      const offset = DATA.groundtruth ? 1 : 0;
      estimates.forEach((e, k) => {
        const ds = chart.data.datasets[offset + k];
        const base = COLOURS[k % COLOURS.length];
        ds.segment = mode === 'estimate' ? undefined : {
          borderColor: (ctx) => mode === 'error' ? errorColour(e.ate[ctx.p0DataIndex], maxAte) : SOURCE_COLOURS[e.source[ctx.p0DataIndex]] || base,
        };
        ds.borderWidth = mode === 'estimate' ? 1.2 : 2;
      });
      chart.update();
    }
  };
  select.addEventListener('change', recolour);
  if (DATA.groundtruth) { select.value = 'error'; recolour(); }
}
