// Error over time (ATE after alignment, RPE per 1 m and 10 m of path) and
// evo's statistics table of each series.
function errorSection() {
  const withErrors = DATA.estimates.filter((e) => e.errors);
  if (!withErrors.length) return;
  const s = section('Error over time', 'ATE: distance to the ground truth after the alignment named in the table. ' +
    'RPE: translation error between pose pairs 1 m and 10 m of path apart (evo\'s definitions, no alignment).');
  const rows = [];
  const series = (name) => withErrors.map((e, k) => {
    const found = e.errors.series.find((x) => x.name.startsWith(name));
    return found ? { entry: e, k, series: found } : null;
  }).filter((x) => x);
  const plot = (id, title, prefix, unit) => {
    const datasets = series(prefix).map(({ entry, k, series: x }) =>
      lineDataset(entry.trajectory.name + ': ' + x.name, points(x.t.map(rel), x.v), COLOURS[k % COLOURS.length],
        { pointRadius: x.v.length < 200 ? 2 : 0 }));
    if (datasets.some((d) => d.data.length)) makeChart(s, id, title, datasets, { yTitle: unit });
  };
  plot('err-ate', 'ATE over time', 'ATE', 'm');
  plot('err-rpe1', 'RPE per 1 m (translation) over time', 'RPE 1 m, translation', 'm');
  plot('err-rpe10', 'RPE per 10 m (translation) over time', 'RPE 10 m, translation', 'm');
  for (const e of withErrors)
    for (const x of e.errors.series) {
      const st = x.stats;
      rows.push([e.trajectory.name, x.name, x.unit, st.count, fmtNum(st.rmse, 4), fmtNum(st.mean, 4), fmtNum(st.median, 4),
        fmtNum(st.std, 4), fmtNum(st.min, 4), fmtNum(st.max, 4), fmtNum(st.sse, 4)]);
    }
  s.append(el('h3', { text: 'Statistics (as evo prints them)' }));
  s.append(table(['trajectory', 'error', 'unit', 'count', 'rmse', 'mean', 'median', 'std', 'min', 'max', 'sse'], rows));
  s.append(el('p', { class: 'note', text: withErrors.map((e) =>
    `${e.trajectory.name}: ${e.errors.alignment} alignment, scale ${fmtNum(e.errors.scale, 4)}`).join('; ') }));
}
