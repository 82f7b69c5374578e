// slamkit's report page: draws the data embedded in #report-data (eval/report/report_data.h)
// with three.js (inlined before this script). Charts and tables are drawn by hand: no plotting
// library is packaged for a page that must carry everything it uses.
'use strict';

const started = performance.now();
const data = JSON.parse(document.getElementById('report-data').textContent);
const runs = data.runs;

// ---- data decoding ----------------------------------------------------------------------------

function bytesOf(base64) {
  const text = atob(base64);
  const bytes = new Uint8Array(text.length);
  for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
  return bytes.buffer;
}
const float32 = (base64) => new Float32Array(bytesOf(base64));

// ---- formatting ---------------------------------------------------------------------------------

function el(tag, attributes, ...children) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes || {})) {
    if (key === 'text') node.textContent = value;
    else node.setAttribute(key, value);
  }
  for (const child of children) node.append(child);
  return node;
}
const mm = (metres) => (metres === undefined || metres === null ? '–' : (1000 * metres).toFixed(2));
const fixed = (value, digits) =>
  value === undefined || value === null ? '–' : Number(value).toFixed(digits);

// Colours of the runs when several are compared, and of the loop verdicts.
const runColours = ['#4fc3f7', '#ffb74d', '#ba68c8', '#81c784', '#f06292', '#fff176'];
const verdictColours = { true: '#43a047', false: '#e53935', unjudged: '#fdd835' };

// The "turbo" colour map (Google, 2019; Apache-2.0), a polynomial fit of it: low error blue,
// high red.
function turbo(t) {
  t = Math.min(1, Math.max(0, t));
  const r = 0.13572138 + t * (4.6153926 + t * (-42.66032258 + t * (132.13108234 + t * (-152.94239396 + t * 59.28637943))));
  const g = 0.09140261 + t * (2.19418839 + t * (4.84296658 + t * (-14.18503333 + t * (4.27729857 + t * 2.82956604))));
  const b = 0.1066733 + t * (12.64194608 + t * (-60.58204836 + t * (110.36276771 + t * (-89.90310912 + t * 27.34824973))));
  return [Math.min(1, Math.max(0, r)), Math.min(1, Math.max(0, g)), Math.min(1, Math.max(0, b))];
}

// ---- header and notes -------------------------------------------------------------------------

document.getElementById('title').textContent =
  runs.length === 1 ? `${runs[0].name}` : `${runs.length} runs: ${runs.map((r) => r.name).join(' · ')}`;
const notes = document.getElementById('notes');
for (const run of runs) {
  for (const note of run.notes) {
    const bad = note.startsWith('the run is not complete');
    notes.append(el('div', { class: bad ? 'note bad' : 'note', text: `${run.name}: ${note}` }));
  }
}

// ---- the 3D view --------------------------------------------------------------------------------

const canvas = document.getElementById('view3d');
// No multisampling, and every line and point drawn with vertex colours: a software WebGL (a
// headless browser, a machine without a GPU) spends most of the first frame compiling shader
// programs, and these choices leave two (three with a mesh).
const renderer = new THREE.WebGLRenderer({ canvas, antialias: false });
renderer.setPixelRatio(window.devicePixelRatio || 1);
renderer.setClearColor(0x15181e);
const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(50, 1, 0.01, 1000);
const controls = new THREE.OrbitControls(camera, canvas);
controls.screenSpacePanning = true;

const bounds = new THREE.Box3();
const layers = [];  // {run, name, object, swatch}
let maxAte = 0;
for (const run of runs) {
  if (run.trajectory && run.trajectory.ate) {
    for (const e of float32(run.trajectory.ate)) if (e > maxAte) maxAte = e;
  }
}

// Positions with a colour per vertex: `colours` an array, or one colour for every vertex.
function lineGeometry(positions, colours) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  if (!(colours instanceof Float32Array)) {
    const c = new THREE.Color(colours);
    const each = new Float32Array(positions.length);
    for (let i = 0; i < each.length; i += 3) each.set([c.r, c.g, c.b], i);
    colours = each;
  }
  geometry.setAttribute('color', new THREE.BufferAttribute(colours, 3));
  return geometry;
}
const lineMaterial = new THREE.LineBasicMaterial({ vertexColors: THREE.VertexColors });

const pointMaterials = [];
function pointsMaterial(options) {
  const material = new THREE.PointsMaterial(Object.assign({ sizeAttenuation: false, vertexColors: THREE.VertexColors }, options));
  material.baseSize = options.size;
  pointMaterials.push(material);
  return material;
}

function addLayer(run, name, object, swatch, visible) {
  object.visible = visible;
  scene.add(object);
  layers.push({ run, name, object, swatch });
}

// Vertices quantised to 16 bits over a box (the map's and the mesh's), with their colours.
function quantisedGeometry(cloud) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(new Uint16Array(bytesOf(cloud.positions)), 3, true));
  geometry.setAttribute('color', new THREE.BufferAttribute(new Uint8Array(bytesOf(cloud.colours)), 3, true));
  return geometry;
}

// Scale and offset put quantised positions back in metres.
function placeInBox(object, cloud) {
  object.scale.set(cloud.size[0], cloud.size[1], cloud.size[2]);
  object.position.set(cloud.min[0], cloud.min[1], cloud.min[2]);
  bounds.expandByPoint(new THREE.Vector3(...cloud.min));
  bounds.expandByPoint(new THREE.Vector3(cloud.min[0] + cloud.size[0], cloud.min[1] + cloud.size[1], cloud.min[2] + cloud.size[2]));
  return object;
}

function mapLayer(map) {
  return placeInBox(new THREE.Points(quantisedGeometry(map), pointsMaterial({ size: 2 })), map);
}

// The mesh lit (see the lights below) so that its shape reads in its own colours. Only front
// faces are drawn: seen from outside, a room's ceiling and near walls show their backs and
// vanish, so the view looks in.
function meshLayer(mesh) {
  const geometry = quantisedGeometry(mesh);
  geometry.setIndex(new THREE.BufferAttribute(new Uint32Array(bytesOf(mesh.indices)), 1));
  // From the quantised positions: the object's scale turns the normals with them.
  geometry.computeVertexNormals();
  const material = new THREE.MeshLambertMaterial({ vertexColors: THREE.VertexColors });
  return placeInBox(new THREE.Mesh(geometry, material), mesh);
}

function trajectoryLayer(trajectory, runColour) {
  const positions = float32(trajectory.positions);
  const colours = new Float32Array(positions.length);
  const ate = trajectory.ate ? float32(trajectory.ate) : null;
  const plain = new THREE.Color(runColour);
  for (let i = 0; i < trajectory.count; ++i) {
    const c = ate && !Number.isNaN(ate[i]) ? turbo(maxAte > 0 ? ate[i] / maxAte : 0) : [plain.r, plain.g, plain.b];
    colours.set(c, 3 * i);
  }
  const group = new THREE.Group();
  const geometry = lineGeometry(positions, colours);
  geometry.computeBoundingBox();
  bounds.union(geometry.boundingBox);
  group.add(new THREE.Line(geometry, lineMaterial));
  group.add(new THREE.Points(geometry, pointsMaterial({ size: 3 })));
  return group;
}

// A camera glyph per keyframe: a small pyramid looking along the camera's z.
function keyframesLayer(keyframes, colour, size) {
  const poses = float32(keyframes.poses);
  const corners = [[0, 0, 0], [-1, -0.75, 1.2], [1, -0.75, 1.2], [1, 0.75, 1.2], [-1, 0.75, 1.2]];
  const edges = [[0, 1], [0, 2], [0, 3], [0, 4], [1, 2], [2, 3], [3, 4], [4, 1]];
  const vertices = new Float32Array(keyframes.count * edges.length * 6);
  const q = new THREE.Quaternion();
  const v = new THREE.Vector3();
  let k = 0;
  for (let i = 0; i < keyframes.count; ++i) {
    const p = poses.subarray(7 * i, 7 * i + 7);
    q.set(p[3], p[4], p[5], p[6]);
    for (const edge of edges) {
      for (const corner of edge) {
        v.set(...corners[corner]).multiplyScalar(size).applyQuaternion(q);
        vertices.set([v.x + p[0], v.y + p[1], v.z + p[2]], k);
        k += 3;
      }
    }
  }
  return new THREE.LineSegments(lineGeometry(vertices, colour), lineMaterial);
}

function loopsLayer(loops) {
  const vertices = new Float32Array(loops.length * 6);
  const colours = new Float32Array(loops.length * 6);
  loops.forEach((loop, i) => {
    vertices.set([...loop.from, ...loop.to], 6 * i);
    const c = new THREE.Color(verdictColours[loop.verdict] || verdictColours.unjudged);
    colours.set([c.r, c.g, c.b, c.r, c.g, c.b], 6 * i);
  });
  // Lines are one pixel wide in WebGL: dots at both keyframes make a short loop edge visible.
  const geometry = lineGeometry(vertices, colours);
  const group = new THREE.Group();
  group.add(new THREE.LineSegments(geometry, lineMaterial));
  group.add(new THREE.Points(geometry, pointsMaterial({ size: 6 })));
  return group;
}

runs.forEach((run, r) => {
  const colour = runColours[r % runColours.length];
  // A mesh shows the surface better than the points, which would only speckle it: the first
  // run's mesh is shown, its points hidden.
  if (run.map) addLayer(run, `map (${run.map.count.toLocaleString()} points)`, mapLayer(run.map), null, r === 0 && !run.mesh);
  if (run.mesh) addLayer(run, `mesh (${run.mesh.count.toLocaleString()} triangles)`, meshLayer(run.mesh), null, r === 0);
  if (run.groundtruth) {
    const geometry = lineGeometry(float32(run.groundtruth.positions), 0xbfc5cf);
    addLayer(run, 'groundtruth (aligned)', new THREE.Line(geometry, lineMaterial), '#bfc5cf', r === 0);
  }
  if (run.trajectory) {
    addLayer(run, run.trajectory.ate ? 'trajectory, coloured by ATE' : 'trajectory', trajectoryLayer(run.trajectory, colour), colour, true);
  }
  if (run.loops.length > 0) {
    const counts = {};
    for (const loop of run.loops) counts[loop.verdict] = (counts[loop.verdict] || 0) + 1;
    const text = Object.entries(counts).map(([verdict, n]) => `${n} ${verdict}`).join(', ');
    addLayer(run, `loops (${text})`, loopsLayer(run.loops), verdictColours.true, true);
  }
  if (run.lost && run.lost.count > 0) {
    const geometry = lineGeometry(float32(run.lost.positions), 0xff1744);
    addLayer(run, `lost frames (${run.lost.count})`, new THREE.Points(geometry, pointsMaterial({ size: 7 })), '#ff1744', true);
  }
});

const centre = new THREE.Vector3();
const radius = bounds.isEmpty() ? 1 : Math.max(bounds.getSize(new THREE.Vector3()).length() / 2, 0.05);
if (!bounds.isEmpty()) bounds.getCenter(centre);
runs.forEach((run, r) => {
  if (run.keyframes && run.keyframes.count > 0) {
    addLayer(run, `keyframes (${run.keyframes.count})`, keyframesLayer(run.keyframes, runColours[r % runColours.length], radius * 0.008), runColours[r % runColours.length], r === 0);
  }
});

const up = runs.length > 0 ? runs[0].up : [0, 0, 1];
if (runs.some((run) => run.mesh)) {
  // The meshes' lights (points and lines ignore them): a sky light from above, so that floors
  // and walls differ, and a light at the eye, so that every face turned to the view is lit.
  const sky = new THREE.HemisphereLight(0xffffff, 0x505560, 0.6);
  sky.position.set(up[0], up[1], up[2]);
  scene.add(sky);
  camera.add(new THREE.PointLight(0xffffff, 0.5));
  scene.add(camera);
}

function resetView() {
  camera.up.set(up[0], up[1], up[2]);
  // From above and to one side of the scene, looking at its centre.
  const side = new THREE.Vector3(1, 0, 0);
  if (Math.abs(side.dot(camera.up)) > 0.9) side.set(0, 1, 0);
  side.addScaledVector(camera.up, -side.dot(camera.up)).normalize();
  const direction = side.multiplyScalar(0.8).addScaledVector(camera.up, 0.9).normalize();
  camera.position.copy(centre).addScaledVector(direction, radius * 1.9);
  camera.near = radius / 500;
  camera.far = radius * 50;
  camera.updateProjectionMatrix();
  controls.target.copy(centre);
  controls.update();
  render();
}

function resize() {
  const width = canvas.clientWidth, height = canvas.clientHeight;
  renderer.setSize(width, height, false);
  camera.aspect = width / Math.max(1, height);
  camera.updateProjectionMatrix();
  render();
}

let frameRequested = false;
function render() {
  if (frameRequested) return;
  frameRequested = true;
  requestAnimationFrame(() => {
    frameRequested = false;
    renderer.render(scene, camera);
  });
}
controls.addEventListener('change', render);
window.addEventListener('resize', resize);

// ---- layer toggles and the colour bar ---------------------------------------------------------

const layerList = document.getElementById('layer-list');
let shownRun = null;
for (const layer of layers) {
  if (layer.run !== shownRun && runs.length > 1) {
    layerList.append(el('div', { class: 'run-name', text: layer.run.name }));
  }
  shownRun = layer.run;
  const box = el('input', { type: 'checkbox' });
  box.checked = layer.object.visible;
  box.addEventListener('change', () => {
    layer.object.visible = box.checked;
    render();
  });
  const swatch = el('span', { class: 'swatch' });
  swatch.style.background = layer.swatch || 'linear-gradient(90deg,#30123b,#1ae4b6,#fb8022,#7a0403)';
  layerList.append(el('label', { class: 'row' }, box, swatch, layer.name));
}
document.getElementById('reset-view').addEventListener('click', resetView);
document.getElementById('point-size').addEventListener('input', (event) => {
  const factor = Number(event.target.value) / 2;
  for (const material of pointMaterials) material.size = material.baseSize * factor;
  render();
});
const budget = document.getElementById('map-budget');
const mapped = runs.filter((run) => run.map || run.mesh);
const meshed = runs.some((run) => run.mesh);
const shownOf = (run) => [
  run.map && `${run.map.count.toLocaleString()} of ${run.map.total.toLocaleString()} map points`,
  run.mesh && `${run.mesh.count.toLocaleString()} of ${run.mesh.total.toLocaleString()} mesh triangles`,
].filter(Boolean).join(' and ');
budget.className = 'muted';
budget.textContent = mapped.length === 0 ? 'No map in this run.' :
  mapped.map((run) => `${run.name}: ${shownOf(run)} shown`).join('; ') +
  (meshed ? ` (budgets ${data.point_budget.toLocaleString()} points, ${data.mesh_triangle_budget.toLocaleString()} triangles).` :
    ` (budget ${data.point_budget.toLocaleString()}).`);

function drawColourBar() {
  const bar = document.getElementById('colour-bar');
  if (maxAte <= 0) {
    bar.style.display = 'none';
    return;
  }
  const context = document.getElementById('colour-bar-canvas').getContext('2d');
  for (let y = 0; y < 200; ++y) {
    const [r, g, b] = turbo(1 - y / 199);
    context.fillStyle = `rgb(${255 * r},${255 * g},${255 * b})`;
    context.fillRect(0, y, 24, 1);
  }
  const labels = document.getElementById('colour-bar-labels');
  labels.append(el('span', { text: `${mm(maxAte)} mm` }), el('span', { text: 'ATE' }), el('span', { text: '0 mm' }));
}
drawColourBar();

// ---- metrics ----------------------------------------------------------------------------------

function metricsTable() {
  const rows = [
    ['ATE RMSE (mm)', (m) => mm(m.ate && m.ate.rmse)],
    ['ATE mean / median (mm)', (m) => m.ate ? `${mm(m.ate.mean)} / ${mm(m.ate.median)}` : '–'],
    ['ATE std / max (mm)', (m) => m.ate ? `${mm(m.ate.std)} / ${mm(m.ate.max)}` : '–'],
    ['ATE poses', (m) => (m.ate ? m.ate.pairs : '–')],
    ['RPE translation RMSE (mm)', (m) => mm(m.rpe && m.rpe.trans && m.rpe.trans.rmse)],
    ['RPE rotation RMSE (deg)', (m) => fixed(m.rpe && m.rpe.rot_deg && m.rpe.rot_deg.rmse, 3)],
    ['RPE delta', (m) => (m.rpe ? `${m.rpe.delta} ${m.rpe.unit}` : '–')],
    ['map accuracy, mean / median (mm)', (m) => m.map && m.map.accuracy ? `${mm(m.map.accuracy.mean)} / ${mm(m.map.accuracy.median)}` : '–'],
    ['map completeness', (m) => (m.map && m.map.completeness !== undefined ? `${fixed(100 * m.map.completeness, 1)} %` : '–')],
    ['loops accepted / false', (m) => (m.loops_accepted === undefined ? '–' : `${m.loops_accepted} / ${m.loops_false}`)],
    ['loop precision / recall', (m) => (m.loops_accepted === undefined ? '–' : `${fixed(m.loop_precision, 2)} / ${fixed(m.loop_recall, 2)}`)],
  ];
  const runRows = [
    ['frames / lost', (run) => {
      const frames = run.timing && run.timing.frames;
      return frames === undefined ? '–' : `${frames} / ${run.lost ? run.lost.count : '–'}`;
    }],
    ['keyframes', (run) => (run.keyframes ? run.keyframes.count : '–')],
    ['status', (run) => run.status],
    ['version', (run) => (run.run && run.run.version) || '–'],
    ['settings hash', (run) => (run.run && run.run.settings_hash) || '–'],
  ];
  const stageNames = ['prepare', 'track', 'local_ba', 'loops', 'global_ba', 'refine', 'fusion', 'write', 'total'];
  const table = el('table');
  const head = el('tr', {}, el('th', { text: '' }));
  for (const run of runs) head.append(el('th', { text: run.name }));
  table.append(el('thead', {}, head));
  const body = el('tbody');
  const addRow = (label, cell) => {
    const row = el('tr', {}, el('td', { text: label }));
    for (const run of runs) row.append(el('td', { text: String(cell(run)) }));
    body.append(row);
  };
  for (const [label, value] of rows) addRow(label, (run) => (run.metrics ? value(run.metrics) : '–'));
  for (const [label, value] of runRows) addRow(label, value);
  for (const stage of stageNames) {
    addRow(`${stage.replace('_', ' ')} (s)`, (run) => {
      const seconds = run.run && run.run.seconds ? run.run.seconds : run.timing && run.timing.seconds;
      return seconds && seconds[stage] !== undefined ? fixed(seconds[stage], 2) : '–';
    });
  }
  table.append(body);
  return table;
}
document.getElementById('metrics').append(metricsTable());

// ---- the evaluator's plots ----------------------------------------------------------------------

const figures = document.getElementById('figures');
for (const run of runs) {
  for (const [name, svg] of Object.entries(run.figures)) {
    const figure = el('figure');
    figure.innerHTML = svg.replace(/^<\?xml[^>]*>\s*/, '').replace(/<!DOCTYPE[^>]*>\s*/, '');
    figure.append(el('figcaption', { class: 'muted', text: `${run.name}: ${name.replace(/_/g, ' ')}` }));
    figures.append(figure);
  }
}
if (figures.children.length === 0) {
  figures.append(el('p', { class: 'muted', text: 'No plots: the runs have no groundtruth evaluation, or were made with --no-plot.' }));
}

// ---- per-frame diagnostics: line charts on canvases ------------------------------------------

function lineChart(title, series, unit) {
  const wrap = el('div');
  const legend = el('div', { class: 'legend' });
  for (const s of series) {
    const swatch = el('span', { class: 'swatch' });
    swatch.style.background = s.colour;
    legend.append(el('span', {}, swatch, ` ${s.label}`));
  }
  const chart = el('canvas', { class: 'chart' });
  wrap.append(el('div', { class: 'chart-title', text: `${title} (${unit})` }), legend, chart);
  const draw = () => {
    const width = chart.clientWidth, height = chart.clientHeight;
    const ratio = window.devicePixelRatio || 1;
    chart.width = width * ratio;
    chart.height = height * ratio;
    const g = chart.getContext('2d');
    g.scale(ratio, ratio);
    const left = 48, right = 8, top = 6, bottom = 20;
    let xMax = 0, yMax = 0;
    for (const s of series) {
      for (let i = 0; i < s.x.length; ++i) {
        xMax = Math.max(xMax, s.x[i]);
        if (Number.isFinite(s.y[i])) yMax = Math.max(yMax, s.y[i]);
      }
    }
    if (yMax === 0) yMax = 1;
    if (xMax === 0) xMax = 1;
    const px = (x) => left + (x / xMax) * (width - left - right);
    const py = (y) => top + (1 - y / yMax) * (height - top - bottom);
    g.strokeStyle = '#d9dde4';
    g.fillStyle = '#5b6474';
    g.font = '11px system-ui, sans-serif';
    for (let k = 0; k <= 4; ++k) {
      const y = (yMax * k) / 4;
      g.beginPath();
      g.moveTo(left, py(y));
      g.lineTo(width - right, py(y));
      g.stroke();
      g.fillText(y >= 100 ? y.toFixed(0) : y.toPrecision(2), 4, py(y) + 4);
    }
    for (let k = 0; k <= 5; ++k) g.fillText(`${((xMax * k) / 5).toFixed(1)} s`, px((xMax * k) / 5) - 10, height - 4);
    for (const s of series) {
      g.strokeStyle = s.colour;
      g.fillStyle = s.colour;
      if (s.marks) {
        for (let i = 0; i < s.x.length; ++i) if (s.y[i]) g.fillRect(px(s.x[i]) - 0.5, top, 1, height - top - bottom);
        continue;
      }
      g.beginPath();
      for (let i = 0; i < s.x.length; ++i) {
        if (i === 0) g.moveTo(px(s.x[i]), py(s.y[i]));
        else g.lineTo(px(s.x[i]), py(s.y[i]));
      }
      g.stroke();
    }
  };
  return { wrap, draw };
}

const charts = [];
const diagnostics = document.getElementById('diagnostics');
const palette = ['#1565c0', '#ef6c00', '#2e7d32', '#6a1b9a', '#c62828', '#00838f', '#ad1457', '#4e342e'];
for (const run of runs) {
  const f = run.frames;
  if (!f.seconds) continue;
  const x = float32(f.seconds);
  const column = (name) => (f[name] ? float32(f[name]) : null);
  const named = (names) => names.filter((name) => f[name]).map((name, i) => ({ label: name.replace(/_/g, ' '), x, y: column(name), colour: palette[i % palette.length] }));
  const prefix = runs.length > 1 ? `${run.name}: ` : '';
  const counts = named(['features', 'matches', 'pairs_3d', 'inliers']);
  const events = [];
  if (f.keyframe) events.push({ label: 'keyframe', x, y: column('keyframe'), colour: 'rgba(46,125,50,0.35)', marks: true });
  if (f.lost) events.push({ label: 'lost', x, y: column('lost'), colour: 'rgba(229,57,53,0.8)', marks: true });
  charts.push(lineChart(`${prefix}features, matches and inliers per frame`, counts.concat(events), 'count'));
  const steps = named(['decode_ms', 'features_ms', 'window_code_ms', 'match_ms', 'pose_ms', 'refine_ms', 'keyframe_ms', 'mapping_ms']);
  charts.push(lineChart(`${prefix}time of each step per frame`, steps, 'ms'));
}
if (charts.length === 0) diagnostics.append(el('p', { class: 'muted', text: 'No tracking.csv in these runs.' }));
for (const chart of charts) diagnostics.append(chart.wrap);

// ---- the runs: files, settings ------------------------------------------------------------------

const runsSection = document.getElementById('runs');
for (const run of runs) {
  const lines = [`folder ${run.dir}`, `status ${run.status}`];
  if (run.run && run.run.started) lines.push(`started ${run.run.started}, ended ${run.run.ended || '–'}`);
  if (run.metrics && run.metrics.settings) lines.push(`evaluation: ${run.metrics.settings.convention} convention, ${run.metrics.settings.association} association`);
  const block = el('div', {}, el('h3', { text: run.name }), el('p', { class: 'muted', text: lines.join(' · ') }));
  if (run.settings_yaml) block.append(el('details', {}, el('summary', { text: 'settings.yaml' }), el('pre', { text: run.settings_yaml })));
  runsSection.append(block);
}
document.getElementById('footer').textContent = `Written by ${data.generator}. Self-contained: open it anywhere, no network needed.`;

// ---- start ------------------------------------------------------------------------------------

resize();
resetView();
for (const chart of charts) chart.draw();
window.addEventListener('resize', () => charts.forEach((chart) => chart.draw()));
requestAnimationFrame(() => {
  // The first frame is drawn and the controls listen: the page can be used from here.
  window.slamkitReport = { ready: true, interactiveMs: performance.now(), scriptMs: performance.now() - started };
});
