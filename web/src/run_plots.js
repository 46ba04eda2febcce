// The run's own records from stats.json: the summary, the detection module,
// the fusion framework, loop closure (and a saved map) and the time each
// stage took.
function frameSeries(get) {
  const f = DATA.stats.frames;
  return f.map((r) => ({ x: rel(r.t), y: get(r) })).filter((q) => q.y != null && isFinite(q.y));
}

function summarySection() {
  const st = DATA.stats.summary;
  const s = section('Summary');
  const rows = [['mode', st.mode], ['images / scans', `${st.images} / ${st.scans}`],
    ['sequence', fmtNum(st.sequence_seconds, 1) + ' s']];
  if (st.wall_seconds != null) rows.push(['wall time (online / whole run)', `${fmtNum(st.online_seconds, 1)} / ${fmtNum(st.wall_seconds, 1)} s`],
    ['real-time factor (online / whole run)', `${fmtNum(st.online_real_time_factor, 2)}x / ${fmtNum(st.real_time_factor, 2)}x`],
    ['peak memory', fmtNum(st.peak_rss_mib, 0) + ' MiB']);
  if (st.latency_ms) rows.push(['online latency median / p95 / max', `${fmtNum(st.latency_ms.median, 1)} / ${fmtNum(st.latency_ms.p95, 1)} / ${fmtNum(st.latency_ms.max, 1)} ms`]);
  rows.push(['subsystem switches', st.switches], ['gated factors (LiDAR / visual)', `${st.gated_lidar_factors} / ${st.gated_visual_factors}`],
    ['fusion lines per frame', fmtNum(st.fusion_lines_per_frame, 2)], ['share of frames lost', fmtNum(100 * st.lost_fraction, 1) + ' %']);
  if (st.accuracy) rows.push(['ATE rmse online', fmtNum(st.accuracy.ate ? st.accuracy.ate.rmse : null, 4) + ' m']);
  if (st.accuracy_refined) rows.push(['ATE rmse refined', fmtNum(st.accuracy_refined.ate ? st.accuracy_refined.ate.rmse : null, 4) + ' m']);
  if (st.wall_seconds == null) rows.push(['timings', 'none: the run was --deterministic']);
  s.append(table(['', ''], rows));
}

function detectionSection() {
  const st = DATA.stats;
  const s = section('Detection module', 'Which subsystem the online output used per frame, the visual tracking ' +
    'figures the module judges by, and the factors the estimator\'s chi-square gate dropped.');
  const use = frameSeries((r) => (r.pose ? (r.source === 'visual' ? 1 : 0) : -1));
  makeChart(s, 'det-source', 'Subsystem in use (1 visual, 0 LiDAR, -1 no pose), switches as points', [
    lineDataset('in use', use, '#1f77b4', { stepped: true }),
    lineDataset('switch', st.switches.map((w) => ({ x: rel(w.t), y: w.to === 'visual' ? 1 : 0 })), '#d62728', { showLine: false, pointRadius: 4 }),
  ], { yTitle: 'subsystem', aspectRatio: 4 });
  const v = (key) => frameSeries((r) => (r.visual ? r.visual[key] : null));
  if (st.frames.some((r) => r.visual)) makeChart(s, 'det-tracking', 'Tracked points, lines and inlier ratio', [
    lineDataset('tracked points', v('tracked_points'), COLOURS[0]),
    lineDataset('tracked lines', v('tracked_lines'), COLOURS[2]),
    lineDataset('inlier ratio (right axis)', v('inlier_ratio'), COLOURS[1], { yAxisID: 'y1' }),
  ], { scales: { x: { type: 'linear', title: { display: true, text: 'time (s)' } }, y: { title: { display: true, text: 'count' } },
    y1: { position: 'right', min: 0, max: 1, grid: { drawOnChartArea: false } } } });
  const gated = (kind) => frameSeries((r) => (r.gated ? r.gated.filter((g) => g.factor === kind).length : 0));
  makeChart(s, 'det-gated', 'Factors the online estimator gated, per frame', [
    lineDataset('LiDAR', gated('lidar'), COLOURS[4], { showLine: false, pointRadius: 2 }),
    lineDataset('visual', gated('visual'), COLOURS[0], { showLine: false, pointRadius: 2 }),
  ], { scales: { x: { type: 'linear', title: { display: true, text: 'time (s)' } },
    y: { min: 0, suggestedMax: 2, title: { display: true, text: 'factors' } } }, aspectRatio: 4 });
  if (st.switches.length) {
    s.append(el('h3', { text: 'Switches' }));
    s.append(table(['time (s)', 'to', 'reason'], st.switches.map((w) => [fmtNum(rel(w.t), 3), w.to, w.reason])));
  }
}

const CLASS_NAMES = ['ground', 'facade', 'roof', 'pillar', 'beam', 'vertex'];
const CLASS_COLOURS = ['#8c6d31', '#3182bd', '#9e9ac8', '#e6550d', '#31a354', '#de2d26'];

function fusionSection() {
  const st = DATA.stats;
  const s = section('Fusion framework and LiDAR features');
  if (st.frames.some((r) => r.fusion)) makeChart(s, 'fus-lines', 'Fusion lines per frame', [
    lineDataset('fusion lines', frameSeries((r) => (r.fusion ? r.fusion.lines : null)), COLOURS[3]),
    lineDataset('fusion lines added to the visual map', frameSeries((r) => (r.visual ? r.visual.fusion_lines_added : null)), COLOURS[2]),
  ], { yTitle: 'lines' });
  const perClass = st.scans.length && st.scans[0].features_per_class;
  const datasets = perClass
    ? CLASS_NAMES.map((name, c) => lineDataset(name, st.scans.map((r) => ({ x: rel(r.t), y: r.features_per_class[c] })), CLASS_COLOURS[c], { fill: c ? '-1' : 'origin' }))
    : [lineDataset('features (all classes)', st.scans.map((r) => ({ x: rel(r.t), y: r.features })), COLOURS[0])];
  makeChart(s, 'fus-classes', 'LiDAR feature points per scan' + (perClass ? ', per class (stacked)' : ''), datasets, { yTitle: 'points', stacked: !!perClass });
}

// Loop closure's candidates and, with --map-in, each keyframe of the run
// tried against the saved map with its verdict.
function loopSection() {
  const lp = DATA.stats.loop;
  if (!lp) return;
  const s = section('Loop closure and saved map', 'Loop candidates by Scan Context, verified by the ICP and gated ' +
    'by the odometry\'s drift; with --map-in, the run\'s keyframes tried against the saved map.');
  s.append(table(['', ''], [['keyframes', lp.keyframes],
    ['loop candidates / verified / accepted', `${lp.candidates} / ${lp.verified} / ${lp.accepted}`],
    ['keyframe graph on the', `${lp.odometry} trajectory`], ['largest keyframe move', fmtNum(lp.largest_keyframe_move_m, 3) + ' m']]));
  const candidates = (accepted) => lp.candidate_log.filter((c) => c.accepted === accepted)
    .map((c) => ({ x: rel(c.query_t), y: c.descriptor_distance }));
  if (lp.candidate_log.length) makeChart(s, 'loop-candidates', 'Loop candidates: Scan Context distance per query keyframe', [
    lineDataset('accepted', candidates(true), COLOURS[2], { showLine: false, pointRadius: 3 }),
    lineDataset('rejected', candidates(false), COLOURS[1], { showLine: false, pointRadius: 3 }),
  ], { yTitle: 'descriptor distance', aspectRatio: 4 });
  const ml = lp.map_localization;
  if (!ml) return;
  s.append(el('h3', { text: 'Saved map (--map-in)' }));
  const rows = [['localised', ml.localized ? `yes, at ${fmtNum(rel(ml.localized_t), 2)} s` : 'no'], ['keyframes tried', ml.tries]];
  if (ml.localized) rows.push(['verified matches agreeing', ml.agreeing],
    ['the run\'s world in the map (x, y, z)', ml.T_map_odom_xyz.map((v) => fmtNum(v, 3)).join(', ') + ' m']);
  s.append(table(['', ''], rows));
  s.append(table(['time (s)', 'map keyframe', 'descriptor distance', 'verdict'], ml.match_log.map((m) =>
    [fmtNum(rel(m.query_t), 2), m.map_keyframe, fmtNum(m.descriptor_distance, 3), m.taken ? 'taken' : m.reason])));
}

function timingSection() {
  const st = DATA.stats;
  const s = section('Time', 'Stage times per camera frame and per LiDAR scan (stacked), the online output\'s latency ' +
    '(output wall time minus the frame\'s arrival). Real-time factor and peak memory are in the summary.');
  if (!st.frames.length || !st.frames.some((r) => r.time_ms)) { s.append(el('p', { text: 'No timings: the run was --deterministic.' })); return; }
  // The stages the mode ran (lidar mode has none per camera frame).
  const stages = ['extraction', 'depth_hints', 'visual', 'fusion', 'fusion_lines_to_visual']
    .filter((k) => st.frames.some((r) => r.time_ms && r.time_ms[k] != null));
  if (stages.length) makeChart(s, 'time-frame', 'Time per stage per camera frame (stacked)', stages.map((k, i) =>
    lineDataset(k, frameSeries((r) => (r.time_ms && r.time_ms[k] != null ? r.time_ms[k] : 0)), COLOURS[i], { fill: i ? '-1' : 'origin' })), { yTitle: 'ms', stacked: true });
  makeChart(s, 'time-scan', 'Time per stage per LiDAR scan (stacked)', ['prepare', 'register'].map((k, i) =>
    lineDataset(k, st.scans.map((r) => ({ x: rel(r.t), y: r.time_ms ? r.time_ms[k] : 0 })), COLOURS[i + 5], { fill: i ? '-1' : 'origin' })), { yTitle: 'ms', stacked: true });
  makeChart(s, 'time-latency', 'Online output latency per frame', [lineDataset('latency', frameSeries((r) => r.latency_ms), COLOURS[1])], { yTitle: 'ms' });
}
