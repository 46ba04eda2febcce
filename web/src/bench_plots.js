// bench.html: each table of `lvslam bench` (the classic suite, or one
// scenario family) as bars per mode, then the figures with inline bars.
function benchFigure(cell) {
  if (!cell || cell.failure) return null;
  if (cell.lost_fraction > 0.5) return null;  // x in the markdown tables
  return cell.ate_rmse_m ?? cell.ate_mean_m ?? null;
}

function benchCellText(cell, max, colour) {
  if (!cell) return el('td', { text: '' });
  if (cell.failure) return el('td', { text: 'fail', title: cell.failure });
  if (cell.lost_fraction > 0.5) return el('td', { text: 'x' });
  const v = benchFigure(cell);
  const td = el('td');
  if (v != null) td.append(el('span', { class: 'bar', style: `width:${Math.round(60 * v / max)}px;background:${colour}` }), fmtNum(v, 4) + ' m');
  else td.append('n/a');
  const extra = [];
  if (cell.refined_ate_rmse_m != null) extra.push('refined ' + fmtNum(cell.refined_ate_rmse_m, 4));
  if (cell.vision_share != null) extra.push(Math.round(100 * cell.vision_share) + ' % vision');
  extra.push(`${fmtNum(cell.online_real_time_factor, 2)}x online / ${fmtNum(cell.real_time_factor, 2)}x whole run`,
    fmtNum(cell.peak_rss_mib, 0) + ' MiB');
  td.append(el('div', { class: 'note', text: extra.join(', ') }));
  return td;
}

function benchSections() {
  DATA.groups.forEach((g, index) => {
    const s = section(g.name, g.note);
    const datasets = g.columns.map((c, k) => ({
      label: c, data: g.rows.map((r) => benchFigure(r.cells[c])), backgroundColor: COLOURS[k % COLOURS.length],
    }));
    makeChart(s, `bench-${index}`, 'ATE rmse (m) per mode (online; the paper\'s aligned mean in the classic suite); ' +
      'missing bar: failed, lost more than half, or no ground truth', datasets, {
      type: 'bar', parsing: true, labels: g.rows.map((r) => r.name), aspectRatio: 3.2,
      scales: { x: { type: 'category', title: { display: true, text: 'sequence / seed' } }, y: { beginAtZero: true, title: { display: true, text: 'm' } } },
    });
    const max = Math.max(1e-9, ...g.rows.flatMap((r) => g.columns.map((c) => benchFigure(r.cells[c]) || 0)));
    const t = el('table', {}, el('tr', {}, el('th', { text: '' }), ...g.columns.map((c) => el('th', { text: c }))));
    for (const r of g.rows) t.append(el('tr', {}, el('td', { text: r.name }), ...g.columns.map((c, k) => benchCellText(r.cells[c], max, COLOURS[k % COLOURS.length]))));
    s.append(t);
  });
}
