// The 3D view, orbitable (three.js, OrbitControls): the LiDAR map (by
// feature class or height), the online and refined trajectories, the ground
// truth, fusion lines and visual line landmarks (lines.ply's colours), and a
// camera frustum every N frames. Everything is in the run's own world (the
// map's); the ground truth is moved there by the online estimate's alignment.
// It renders on demand (a control's change), so a large map stays fluid.

// three.js ships as ES modules; the page carries their text and imports them
// from blob URLs, the controls with their 'three' import pointed at three's.
async function loadThree() {
  const blobUrl = (text) => URL.createObjectURL(new Blob([text], { type: 'text/javascript' }));
  const threeUrl = blobUrl(document.getElementById('three-module').textContent);
  const controlsText = document.getElementById('orbit-controls-module').textContent.replace(/from\s*['"]three['"]/g, `from '${threeUrl}'`);
  const THREE = await import(threeUrl);
  const { OrbitControls } = await import(blobUrl(controlsText));
  return { THREE, OrbitControls };
}

// p = R^T (p' - t) / s: the ground truth in the estimate's world.
function unalign(p, e) {
  const out = new Float32Array(p.length);
  for (let i = 0; i < p.length; i += 3) {
    const d = [p[i] - e.t[0], p[i + 1] - e.t[1], p[i + 2] - e.t[2]];
    for (let c = 0; c < 3; ++c) out[i + c] = (e.R[c] * d[0] + e.R[3 + c] * d[1] + e.R[6 + c] * d[2]) / e.scale;
  }
  return out;
}

function heightColour(THREE, v, lo, hi) {
  return new THREE.Color().setHSL(0.7 * (1 - Math.max(0, Math.min(1, (v - lo) / Math.max(hi - lo, 1e-6)))), 0.8, 0.5);
}

function mapObject(THREE, up, byClass) {
  const m = DATA.map;
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(m.p, 3));
  const colours = new Float32Array(m.p.length);
  let lo = Infinity, hi = -Infinity;
  for (let i = up; i < m.p.length; i += 3) { lo = Math.min(lo, m.p[i]); hi = Math.max(hi, m.p[i]); }
  for (let i = 0; i < m.cls.length; ++i) {
    const c = byClass ? new THREE.Color(CLASS_COLOURS[m.cls[i]] || '#777777') : heightColour(THREE, m.p[3 * i + up], lo, hi);
    colours.set([c.r, c.g, c.b], 3 * i);
  }
  geometry.setAttribute('color', new THREE.Float32BufferAttribute(colours, 3));
  return new THREE.Points(geometry, new THREE.PointsMaterial({ size: 2, sizeAttenuation: false, vertexColors: true }));
}

function polyline(THREE, p, colour) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(p, 3));
  return new THREE.Line(geometry, new THREE.LineBasicMaterial({ color: colour }));
}

function lineObject(THREE) {
  const l = DATA.lines;
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(l.p, 3));
  const colours = new Float32Array(l.p.length);
  for (let i = 0; i < l.rgb.length / 3; ++i)
    for (const end of [0, 1]) colours.set([l.rgb[3 * i] / 255, l.rgb[3 * i + 1] / 255, l.rgb[3 * i + 2] / 255], 6 * i + 3 * end);
  geometry.setAttribute('color', new THREE.Float32BufferAttribute(colours, 3));
  return new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ vertexColors: true }));
}

// A pyramid of 8 edges per frame, apex at the camera, looking along its +z.
function frustumObject(THREE, traj, every, size) {
  const corners = [[-1, -0.75, 1.5], [1, -0.75, 1.5], [1, 0.75, 1.5], [-1, 0.75, 1.5]].map((c) => new THREE.Vector3(...c).multiplyScalar(size));
  const positions = [];
  for (let i = 0; i < traj.t.length; i += every) {
    const q = new THREE.Quaternion(traj.q[4 * i], traj.q[4 * i + 1], traj.q[4 * i + 2], traj.q[4 * i + 3]);
    const o = new THREE.Vector3(traj.p[3 * i], traj.p[3 * i + 1], traj.p[3 * i + 2]);
    const w = corners.map((c) => c.clone().applyQuaternion(q).add(o));
    for (let k = 0; k < 4; ++k) positions.push(...o.toArray(), ...w[k].toArray(), ...w[k].toArray(), ...w[(k + 1) % 4].toArray());
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
  return new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: '#555555' }));
}

async function view3dSection(three) {
  const m = DATA.map;
  const note = m ? (m.voxel_m > 0
    ? `LiDAR map decimated for display: ${m.cls.length} of ${m.points_total} points, the first of each ${fmtNum(m.voxel_m * 100, 1)} cm voxel (map.ply has them all).`
    : `LiDAR map: all ${m.points_total} points.`) : 'No map.ply in this run.';
  const s = section('3D view', note + ' Drag to orbit, right-drag to pan, wheel to zoom.');
  const controls = el('div', { class: 'controls' });
  const container = el('div', { class: 'view3d' });
  s.append(controls, container);
  const { THREE, OrbitControls } = await three;
  const up = upAxis();
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  const width = container.clientWidth || 900, height = Math.round(width * 0.6);
  renderer.setSize(width, height);
  renderer.setClearColor('#ffffff');
  renderer.domElement.id = 'view3d-canvas';
  container.append(renderer.domElement);
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(50, width / height, 0.05, 5000);
  camera.up.set(...[0, 1, 2].map((a) => (a === up ? 1 : 0)));
  const layers = {};
  const online = DATA.estimates[0];
  // The map in both colourings; a choice shows one of them.
  const byClass = m && mapObject(THREE, up, true), byHeight = m && mapObject(THREE, up, false);
  if (m) { layers['LiDAR map'] = new THREE.Group(); layers['LiDAR map'].add(byClass, byHeight); byHeight.visible = false; }
  DATA.estimates.forEach((e, k) => { layers[e.trajectory.name] = polyline(THREE, e.trajectory.p, COLOURS[k % COLOURS.length]); });
  if (DATA.groundtruth && online.errors) layers[DATA.groundtruth.name] = polyline(THREE, unalign(DATA.groundtruth.p, online.errors), '#444444');
  if (DATA.lines && DATA.lines.p.length) layers['fusion lines (red), visual line landmarks (green/orange)'] = lineObject(THREE);
  const isCamera = !DATA.stats || DATA.stats.summary.mode !== 'lidar';
  const every = Math.max(1, Math.ceil(online.trajectory.t.length / 80));
  if (isCamera && online.trajectory.t.length) layers[`camera frustums (every ${every} frames)`] = frustumObject(THREE, online.trajectory, every, 0.1);
  const render = () => renderer.render(scene, camera);
  for (const [name, object] of Object.entries(layers)) {
    const box = el('input', { type: 'checkbox' });
    box.checked = true;
    box.addEventListener('change', () => { object.visible = box.checked; render(); });
    controls.append(el('label', {}, box, ' ' + name));
    scene.add(object);
  }
  if (m) {
    const colouring = el('select', { id: 'map-colour' }, el('option', { value: 'class', text: 'feature class' }),
      el('option', { value: 'height', text: 'height' }));
    colouring.addEventListener('change', () => {
      byClass.visible = colouring.value === 'class';
      byHeight.visible = !byClass.visible;
      render();
    });
    const legend = el('span', { class: 'note' }, ...CLASS_NAMES.map((name, c) =>
      el('span', { style: `color:${CLASS_COLOURS[c]};margin-right:8px`, text: '\u25cf ' + name })));
    controls.append(el('label', { text: 'map colour: ' }, colouring), legend);
  }
  // Frame the map and the trajectories (a stray line landmark far out would
  // shrink everything else to a dot).
  const bounds = new THREE.Box3();
  for (const [name, object] of Object.entries(layers)) if (!name.startsWith('fusion lines')) bounds.expandByObject(object);
  const centre = bounds.getCenter(new THREE.Vector3()), size = bounds.getSize(new THREE.Vector3()).length() || 1;
  const view = new THREE.Vector3(1, 1, 1).setComponent(up, 1.2).normalize();
  camera.position.copy(centre).addScaledVector(view, 0.8 * size);
  const orbit = new OrbitControls(camera, renderer.domElement);
  orbit.target.copy(centre);
  orbit.update();
  orbit.addEventListener('change', render);
  render();
  LV.view3d = { renderer, scene, camera, render };
}
