// GRPVSS report viewer: reads the JSON report embedded in the page (#grpvss-report), draws the
// robot, obstacles, expanded hulls and interference points with three.js, and plays the path in
// the thesis's two modes (continuous animation, step by step). No network access.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { buildScene, setPose, starTexture, COLORS } from './scene_builder.js';
import { drawTimeline, drawClearancePlot, stepClass, LINK_COLORS } from './plots.js';

const report = JSON.parse(document.getElementById('grpvss-report').textContent);
const $ = (id) => document.getElementById(id);
const steps = report.steps;
const scene = report.scene;

function fmt(value, digits = 3) {
  return value === null || value === undefined ? '—' : Number(value).toFixed(digits);
}
// A proven lower bound with `digits` decimals, rounded down (toFixed rounds to nearest and
// could print 0.6907 for 0.69065..., a clearance nobody proved).
function fmtLowerBound(value, digits = 4) {
  if (value === null || value === undefined) return '—';
  let text = Number(value).toFixed(digits);
  if (Number(text) > value) text = (Number(text) - 10 ** -digits).toFixed(digits);
  return text;
}
function escapeHtml(text) {
  return String(text).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' }[c]));
}

// ---- three.js scene ------------------------------------------------------------------------
const container = $('view');
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio || 1);
container.appendChild(renderer.domElement);
const world = new THREE.Scene();
world.background = new THREE.Color(COLORS.background);
world.add(new THREE.AmbientLight(0xffffff, 0.55));
const sun = new THREE.DirectionalLight(0xffffff, 1.6);
sun.position.set(60, -80, 120);
world.add(sun);
const fillLight = new THREE.DirectionalLight(0xffffff, 0.5);
fillLight.position.set(-80, 60, 40);
world.add(fillLight);

const built = buildScene(scene);
world.add(built.root);

// World frame W has z up (the robot's base frame).
const camera = new THREE.PerspectiveCamera(40, 1, 0.1, 5000);
camera.up.set(0, 0, 1);
const controls = new OrbitControls(camera, renderer.domElement);
controls.enableDamping = false;

const stars = new THREE.Points(
  new THREE.BufferGeometry(),
  new THREE.PointsMaterial({ map: starTexture(), size: 22, sizeAttenuation: false, transparent: true,
    alphaTest: 0.3, depthTest: false, color: 0xffffff }),
);
stars.renderOrder = 10;
world.add(stars);

// A floor grid and axes give scale; the grid spacing is 10 length units.
const bounds = new THREE.Box3();
function frameCamera() {
  bounds.makeEmpty();
  for (let s = 0; s < scene.steps.length; s += Math.max(1, Math.floor(scene.steps.length / 40))) {
    applyPoses(s);
    built.root.updateMatrixWorld(true);
    bounds.expandByObject(built.root);
  }
  if (bounds.isEmpty()) bounds.set(new THREE.Vector3(-50, -50, 0), new THREE.Vector3(50, 50, 50));
  const center = bounds.getCenter(new THREE.Vector3());
  const radius = bounds.getSize(new THREE.Vector3()).length() / 2;
  const grid = new THREE.GridHelper(Math.ceil((radius * 2.4) / 10) * 10, Math.ceil((radius * 2.4) / 10));
  grid.rotation.x = Math.PI / 2;
  grid.position.set(center.x, center.y, Math.min(0, bounds.min.z));
  grid.material.transparent = true;
  grid.material.opacity = 0.35;
  world.add(grid);
  const axes = new THREE.AxesHelper(radius * 0.25);
  world.add(axes);
  viewRadius = radius;
  viewCenter.copy(center);
  camera.near = radius / 100;
  camera.far = radius * 50;
  thesisView();
}

// The thesis's default view (A.2: ANGLEX, ANGLEY, ANGLEZ = -75, 0, 170 deg; the world frame
// turned from the screen frame S, x right, y up, z out of the screen): the eye looks along
// -z_S, so it sits at R^T z_S from the centre, R = Rx(ax) Ry(ay) Rz(az). Same as `grpvss render`.
const viewCenter = new THREE.Vector3();
let viewRadius = 50;
function thesisView() {
  const deg = Math.PI / 180;
  const R_SW = new THREE.Matrix4().makeRotationX(-75 * deg)
    .multiply(new THREE.Matrix4().makeRotationY(0))
    .multiply(new THREE.Matrix4().makeRotationZ(170 * deg));
  const eye_W = new THREE.Vector3(0, 0, 1).applyMatrix4(R_SW.transpose()).normalize();
  controls.target.copy(viewCenter);
  camera.position.copy(viewCenter).addScaledVector(eye_W, viewRadius * 2.4);
  camera.updateProjectionMatrix();
  controls.update();
}

// ---- state ---------------------------------------------------------------------------------
const state = {
  step: 0, // index into report.steps
  playing: false,
  mode: 'continuous', // 'continuous' (real time along path_time) or 'step' (one step per tick)
  speed: 1,
  display: 'both',
  expanded: false,
  pathTime: 0,
};

function applyPoses(index) {
  const poses = scene.steps[index]?.X_WL ?? scene.start?.X_WL;
  if (!poses) return;
  built.links.forEach((group, link) => setPose(group, poses[link]));
}

function applyDisplay() {
  const wire = state.display !== 'shaded';
  const fill = state.display !== 'wireframe';
  built.linkWires.forEach((o) => { o.visible = wire; });
  built.linkFills.forEach((o) => { o.visible = fill; });
  built.obstacleWires.forEach((o) => { o.visible = wire; });
  built.obstacleFills.forEach((o) => { o.visible = fill; });
  built.expanded.forEach((o, k) => {
    // pairs: fill, wire
    o.visible = state.expanded && (k % 2 === 0 ? fill : true);
  });
}

function endEffectorOrientation(rows) {
  // Rotation of X_WE as axis and angle (the path file's orientation form), degrees.
  const m = new THREE.Matrix4().set(...rows);
  const q = new THREE.Quaternion().setFromRotationMatrix(m);
  const angle = 2 * Math.acos(Math.min(1, Math.abs(q.w)));
  const s = Math.sqrt(Math.max(0, 1 - q.w * q.w));
  const sign = q.w < 0 ? -1 : 1;
  const axis = s < 1e-9 ? [0, 0, 1] : [sign * q.x / s, sign * q.y / s, sign * q.z / s];
  return { axis, angle: (angle * 180) / Math.PI, approach: [rows[2], rows[6], rows[10]] };
}

function segmentKind(number) {
  const segment = report.segments.find((s) => s.number === number);
  return segment ? segment.kind : '';
}

function showStep(index) {
  if (steps.length === 0) return;
  state.step = Math.max(0, Math.min(steps.length - 1, index));
  const step = steps[state.step];
  state.pathTime = step.path_time;
  applyPoses(state.step);
  const positions = [];
  for (const point of step.interference_points) positions.push(...point.point);
  stars.geometry.dispose();
  stars.geometry = new THREE.BufferGeometry();
  stars.geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
  stars.visible = positions.length > 0;

  const units = report.robot.joint_types.map((t) => (t === 'revolute' ? '°' : ''));
  const poses = scene.steps[state.step].X_WL;
  const ee = poses[poses.length - 1];
  const orientation = endEffectorOrientation(ee);
  const kind = stepClass(step);
  const status = kind === 'collision' ? '<span class="bad">COLLISION</span>'
    : kind === 'tolerance' ? '<span class="warn">within tolerance</span>' : '<span class="ok">clear</span>';
  $('step-panel').innerHTML = `
    <table>
      <tr><th>Step</th><td id="step-number">${step.index}</td><th>of</th><td>${steps[steps.length - 1].index}</td></tr>
      <tr><th>Time</th><td colspan="3">${fmt(step.path_time, 3)} s</td></tr>
      <tr><th>Segment</th><td colspan="3">${step.segment} (${escapeHtml(segmentKind(step.segment))})${step.refinement ? ' refined' : ''}</td></tr>
      <tr><th>Status</th><td colspan="3">${status}</td></tr>
      <tr><th>Interference points</th><td colspan="3" id="interference-count">${step.interference_points.length}</td></tr>
    </table>
    <h3>Joint values</h3>
    <table>${step.joint_values.map((v, j) => `<tr><th>q${j + 1}</th><td>${fmt(v, 3)}${units[j]}</td></tr>`).join('')}</table>
    <h3>End effector</h3>
    <table>
      <tr><th>position</th><td>${fmt(ee[3], 3)}, ${fmt(ee[7], 3)}, ${fmt(ee[11], 3)}</td></tr>
      <tr><th>axis</th><td>${orientation.axis.map((v) => fmt(v, 3)).join(', ')}</td></tr>
      <tr><th>angle</th><td>${fmt(orientation.angle, 2)}°</td></tr>
      <tr><th>approach (z)</th><td>${orientation.approach.map((v) => fmt(v, 3)).join(', ')}</td></tr>
    </table>
    <h3>Link clearance</h3>
    <table>${step.links.filter((l) => l.link > 0).map((l) => `<tr><th><span class="swatch" style="background:${LINK_COLORS[l.link % LINK_COLORS.length]}"></span>link ${l.link}</th><td>${fmtLowerBound(l.clearance, 4)}</td></tr>`).join('')}</table>`;
  $('timeline-range').value = String(state.step);
  redraw2d();
  render();
}

function redraw2d() {
  drawTimeline($('timeline'), steps, state.step);
  drawClearancePlot($('clearance'), steps, state.step, report.robot.joint_count + 1);
}

function render() {
  renderer.render(world, camera);
}

function resize() {
  const width = container.clientWidth;
  const height = container.clientHeight;
  renderer.setSize(width, height, false);
  renderer.domElement.style.width = `${width}px`;
  renderer.domElement.style.height = `${height}px`;
  camera.aspect = width / Math.max(1, height);
  camera.updateProjectionMatrix();
  redraw2d();
  render();
}

// ---- playback ------------------------------------------------------------------------------
let lastFrame = 0;
let stepTimer = 0;
function tick(now) {
  if (!state.playing) return;
  const dt = lastFrame ? (now - lastFrame) / 1000 : 0;
  lastFrame = now;
  if (state.mode === 'continuous') {
    // Real time along the path: show the last step whose path_time has been reached.
    state.pathTime += dt * state.speed;
    let next = state.step;
    while (next + 1 < steps.length && steps[next + 1].path_time <= state.pathTime) ++next;
    if (next !== state.step) { const t = state.pathTime; showStep(next); state.pathTime = t; }
    if (state.step === steps.length - 1) stop();
  } else {
    stepTimer += dt * state.speed;
    if (stepTimer >= 0.25) {
      stepTimer = 0;
      if (state.step + 1 < steps.length) showStep(state.step + 1); else stop();
    }
  }
  if (state.playing) requestAnimationFrame(tick);
}
function play() {
  if (state.playing || steps.length === 0) return;
  if (state.step === steps.length - 1) showStep(0);
  state.playing = true;
  lastFrame = 0;
  stepTimer = 0;
  $('play').textContent = '❚❚ Pause';
  requestAnimationFrame(tick);
}
function stop() {
  state.playing = false;
  $('play').textContent = '▶ Play';
}

// ---- static panels -------------------------------------------------------------------------
function auditPanel() {
  const verdictClass = report.verdict === 'CLEAR' ? 'ok' : report.verdict === 'WITHIN_TOLERANCE' ? 'warn' : 'bad';
  const inputs = ['robot', 'environment', 'path'].map((k) => `<tr><th>${k}</th><td>${escapeHtml(report.inputs[k].file)}<br><code>${report.inputs[k].sha256}</code></td></tr>`).join('');
  const clearances = report.link_clearances.filter((c) => c.link > 0)
    .map((c) => `<tr><th>link ${c.link}</th><td>${fmtLowerBound(c.min_clearance, 4)} at step ${c.step}${c.min_motion_clearance === null
      ? '' : `; along the motion &gt; ${fmtLowerBound(c.min_motion_clearance, 4)} (steps ${c.motion_step - 1}–${c.motion_step})`}</td></tr>`).join('');
  const errors = report.errors.map((e) => `<li>error ${e.code} (segment ${e.segment}, step ${e.step}): ${escapeHtml(e.message)}</li>`).join('');
  // One row per interference episode; its button shows the first colliding step (else the first
  // interfering one). A certified run does not sample a pair while it collides, so the episode
  // ends somewhere before the step at which the pair is clear again ("clear by").
  const range = (a, b) => (a === b ? `step ${a}` : `steps ${a}–${b}`);
  const episodes = report.interference_episodes.map((e) => {
    const collides = e.first_collision_step !== null;
    const target = collides ? e.first_collision_step : e.first_step;
    return `<tr class="episode"><th><button class="episode-go" data-step="${target}" title="show step ${target}">link ${e.link} hull ${e.hull} / obstacle ${e.obstacle}</button></th>
      <td>${range(e.first_step, e.last_step)} (${fmt(e.first_time, 2)}–${fmt(e.last_time, 2)} s${e.cleared_time === null
        ? '' : `, <span class="cleared">clear by ${fmt(e.cleared_time, 2)} s</span>`})<br>${collides
        ? `<span class="bad">collides ${range(e.first_collision_step, e.last_collision_step)}</span>`
        : '<span class="warn">expanded hull only</span>'}</td></tr>`;
  }).join('');
  const certified = report.mode === 'certified';
  $('audit-panel').innerHTML = `
    <div class="verdict ${verdictClass}" id="verdict">${escapeHtml(report.verdict)}</div>
    <table>
      <tr><th>Robot</th><td>${escapeHtml(report.robot.name)} (${report.robot.joint_count} joints)</td></tr>
      <tr><th>Mode</th><td>${escapeHtml(report.mode)}${certified ? '' : ' — NOT certified'}</td></tr>
      <tr><th>Tolerance</th><td>${report.tolerance}</td></tr>
      <tr><th>Expansion</th><td>radius ${fmt(scene.expansion.radius, 6)}, ${escapeHtml(scene.expansion.shape)}</td></tr>
      <tr><th>Steps</th><td>${report.total_steps}; cycle time ${fmt(report.total_cycle_time, 3)} s</td></tr>
      <tr><th>First collision</th><td>${report.collision_step === null ? 'none' : `step ${report.collision_step}`}</td></tr>
    </table>
    <h3>Certificate summary</h3>
    <p class="small">${certified
      ? 'Certified mode: every transition between consecutive steps is covered by the two-ball rule; the verdict above is decided exactly. Re-check with <code>grpvss check-certificate</code>.'
      : 'Thesis mode reproduces the thesis step rule and proves nothing.'}</p>
    <table>${clearances}</table>
    <h3>Interference episodes</h3>
    ${episodes ? `<table id="episodes">${episodes}</table>` : '<p class="small">none: no step has an interfering pair</p>'}
    ${errors ? `<h3>Errors</h3><ul>${errors}</ul>` : ''}
    <h3>Inputs (SHA-256)</h3>
    <table class="digests">${inputs}</table>
    <p class="small">${escapeHtml(report.program.name)} ${escapeHtml(report.program.version)}, report ${escapeHtml(report.schema)}, generated ${escapeHtml(report.generated_at)}</p>`;
}

// The episode buttons jump to their step (the start configuration, step 0, is not animated: the
// first step stands for it).
function wireEpisodeButtons() {
  for (const button of document.querySelectorAll('#episodes button.episode-go')) {
    button.addEventListener('click', () => {
      stop();
      const wanted = Number(button.dataset.step);
      const position = steps.findIndex((s) => s.index >= wanted);
      showStep(position >= 0 ? position : steps.length - 1);
    });
  }
}

// ---- wiring --------------------------------------------------------------------------------
$('title').textContent = `GRPVSS — ${report.robot.name} — ${report.path_file_label}`;
$('timeline-range').max = String(Math.max(0, steps.length - 1));
$('timeline-range').addEventListener('input', (e) => { stop(); showStep(Number(e.target.value)); });
$('play').addEventListener('click', () => (state.playing ? stop() : play()));
$('next').addEventListener('click', () => { stop(); showStep(state.step + 1); });
$('prev').addEventListener('click', () => { stop(); showStep(state.step - 1); });
$('first').addEventListener('click', () => { stop(); showStep(0); });
$('last').addEventListener('click', () => { stop(); showStep(steps.length - 1); });
$('next-interference').addEventListener('click', () => {
  stop();
  for (let i = state.step + 1; i < steps.length; ++i) {
    if (steps[i].interference_points.length > 0) { showStep(i); return; }
  }
});
$('reset-view').addEventListener('click', () => { thesisView(); render(); });
$('mode').addEventListener('change', (e) => { state.mode = e.target.value; });
$('speed').addEventListener('change', (e) => { state.speed = Number(e.target.value); });
$('display').addEventListener('change', (e) => { state.display = e.target.value; applyDisplay(); render(); });
$('expanded').addEventListener('change', (e) => { state.expanded = e.target.checked; applyDisplay(); render(); });
controls.addEventListener('change', render);
window.addEventListener('resize', resize);
window.addEventListener('keydown', (e) => {
  if (e.key === 'ArrowRight') $('next').click();
  else if (e.key === 'ArrowLeft') $('prev').click();
  else if (e.key === ' ') { e.preventDefault(); $('play').click(); }
});

frameCamera();
auditPanel();
wireEpisodeButtons();
applyDisplay();
resize();
showStep(0);

// Read-only inspection API for tests and curious users: counts and the current step's state.
window.grpvssViewer = Object.freeze({
  counts: Object.freeze({
    linkHulls: built.hullCount,
    obstacles: built.obstacleFills.length,
    links: built.links.length,
    steps: steps.length,
  }),
  state() {
    const step = steps[state.step];
    return {
      stepIndex: state.step,
      step: step ? step.index : null,
      pathTime: step ? step.path_time : null,
      playing: state.playing,
      mode: state.mode,
      display: state.display,
      expandedVisible: state.expanded,
      starsVisible: stars.visible,
      starCount: stars.geometry.getAttribute('position') ? stars.geometry.getAttribute('position').count : 0,
      interferenceCountShown: Number($('interference-count')?.textContent ?? NaN),
      verdictShown: $('verdict')?.textContent ?? null,
      episodesShown: document.querySelectorAll('#episodes tr.episode').length,
    };
  },
});
