// GRPVSS report viewer: reads the JSON report embedded in the page (#grpvss-report), draws the
// robot, obstacles, expanded hulls and interference points with three.js, and plays the path in
// the thesis's two modes (continuous animation, step by step). No network access.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { buildScene, setPose, starTexture, COLORS } from './scene_builder.js';
import { drawTimeline, drawClearancePlot, stepClass, LINK_COLORS } from './plots.js';
import { makeNames } from './names.js';

const report = JSON.parse(document.getElementById('grpvss-report').textContent);
const $ = (id) => document.getElementById(id);
const scene = report.scene;
const names = makeNames(scene);
// Links with hulls (link 0, the base, too when it has hulls in the world): the clearance lists.
const checkedLinks = scene.links.filter((l) => l.hulls.length > 0).map((l) => l.link);

// The start configuration (step 0) has no record in report.steps; it is drawn from the scene's
// start poses. Its joint values are the first segment's start, its clearances the ones
// link_clearances reports at step 0 (others are not in the report: null), its status that of
// the interference episodes beginning there. Interference points at step 0 are not in the report.
function startStep() {
  const first = report.segments.find((s) => s.start_joint_values !== null);
  const atStart = report.interference_episodes.filter((e) => e.first_step === 0);
  const links = scene.links.map((l) => {
    const c = report.link_clearances.find((r) => r.link === l.link && r.step === 0);
    return { link: l.link, clearance: c ? c.min_clearance : null };
  });
  return {
    index: 0, segment: 0, path_time: 0, start: true, refinement: false,
    joint_values: first ? first.start_joint_values : [], links, interference_points: [], contacts: [],
    expanded_interferes: atStart.length > 0, unexpanded_collides: atStart.some((e) => e.first_collision_step === 0),
  };
}
const hasStart = Boolean(scene.start) && report.steps.length > 0;
const steps = hasStart ? [startStep(), ...report.steps] : report.steps;
const stepPoses = hasStart ? [scene.start.X_WL, ...scene.steps.map((s) => s.X_WL)] : scene.steps.map((s) => s.X_WL);

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
  for (let s = 0; s < stepPoses.length; s += Math.max(1, Math.floor(stepPoses.length / 40))) {
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
  const poses = stepPoses[index] ?? scene.start?.X_WL;
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
  const poses = stepPoses[state.step];
  const ee = poses[poses.length - 1];
  const orientation = endEffectorOrientation(ee);
  const kind = stepClass(step);
  const status = kind === 'collision' ? '<span class="bad">COLLISION</span>'
    : kind === 'tolerance' ? '<span class="warn">within tolerance</span>' : '<span class="ok">clear</span>';
  $('step-panel').innerHTML = `
    <table>
      <tr><th>Step</th><td id="step-number">${step.index}</td><th>of</th><td>${steps[steps.length - 1].index}</td></tr>
      <tr><th>Time</th><td colspan="3">${fmt(step.path_time, 3)} s</td></tr>
      <tr><th>Segment</th><td colspan="3">${step.start ? 'start configuration' : `${step.segment} (${escapeHtml(segmentKind(step.segment))})${step.refinement ? ' refined' : ''}`}</td></tr>
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
    <table id="step-clearances">${step.links.filter((l) => checkedLinks.includes(l.link)).map((l) => `<tr data-link="${l.link}"><th><span class="swatch" style="background:${LINK_COLORS[l.link % LINK_COLORS.length]}"></span>${escapeHtml(names.link(l.link))}</th><td>${fmtLowerBound(l.clearance, 4)}</td></tr>`).join('')}</table>
    ${step.start ? '<p class="small">Step 0: the start configuration; the report holds its clearances only where a link\'s smallest clearance is there.</p>' : ''}`;
  $('timeline-range').value = String(state.step);
  redraw2d();
  render();
}

function redraw2d() {
  drawTimeline($('timeline'), steps, state.step);
  drawClearancePlot($('clearance'), steps, state.step, checkedLinks, (link) => names.linkShort(link));
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
  const clearances = report.link_clearances.filter((c) => checkedLinks.includes(c.link))
    .map((c) => `<tr data-link="${c.link}"><th>${escapeHtml(names.link(c.link))}</th><td>${fmtLowerBound(c.min_clearance, 4)} at step ${c.step}${c.obstacle === null ? '' : ` from ${escapeHtml(names.obstacle(c.obstacle))}`}${c.min_motion_clearance === null
      ? '' : `; along the motion &gt; ${fmtLowerBound(c.min_motion_clearance, 4)} (steps ${c.motion_step - 1}–${c.motion_step})`}</td></tr>`).join('');
  const errors = report.errors.map((e) => `<li>error ${e.code} (segment ${e.segment}, step ${e.step}): ${escapeHtml(e.message)}</li>`).join('');
  // One row per interference episode; its button shows the first colliding step (else the first
  // interfering one). A certified run does not sample a pair while it collides, so the episode
  // ends somewhere before the step at which the pair is clear again ("clear by").
  const range = (a, b) => (a === b ? `step ${a}` : `steps ${a}–${b}`);
  const episodes = report.interference_episodes.map((e) => {
    const collides = e.first_collision_step !== null;
    const target = collides ? e.first_collision_step : e.first_step;
    return `<tr class="episode"><th><button class="episode-go" data-step="${target}" title="show step ${target}">${escapeHtml(names.pair(e.link, e.hull, e.obstacle))}</button></th>
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
      ${report.motion_model ? `<tr><th>Motion</th><td id="motion">${escapeHtml(report.motion_model)}</td></tr>` : ''}
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

// The episode buttons jump to their step (step 0 is the start configuration).
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

// ---- hover: the name of the link hull or obstacle under the pointer ------------------------
const raycaster = new THREE.Raycaster();
const pickable = [...built.linkFills, ...built.obstacleFills]; // picked even when drawn as wireframe
function pickAt(clientX, clientY) {
  const rect = renderer.domElement.getBoundingClientRect();
  const ndc = new THREE.Vector2(((clientX - rect.left) / rect.width) * 2 - 1,
    -((clientY - rect.top) / rect.height) * 2 + 1);
  raycaster.setFromCamera(ndc, camera);
  built.root.updateMatrixWorld(true);
  const hit = raycaster.intersectObjects(pickable, false)[0];
  return hit ? hit.object.userData : null;
}
function showHover(event) {
  const label = $('hover-label');
  const data = pickAt(event.clientX, event.clientY);
  if (!data) { label.hidden = true; return; }
  const rect = container.getBoundingClientRect();
  label.textContent = names.hover(data);
  label.style.left = `${event.clientX - rect.left + 14}px`;
  label.style.top = `${event.clientY - rect.top + 12}px`;
  label.hidden = false;
}
const sameTarget = (data, target) => (target.obstacle !== undefined
  ? data.kind === 'obstacle' && data.obstacle === target.obstacle
  : data.kind === 'link' && data.link === target.link && data.hull === target.hull);
function visiblePointOf(target) {
  const object = pickable.find((o) => sameTarget(o.userData, target));
  if (!object) return null;
  built.root.updateMatrixWorld(true);
  const positions = object.geometry.getAttribute('position');
  const rect = renderer.domElement.getBoundingClientRect();
  // Candidates: each triangle's centroid, in the world, projected to the page.
  for (let i = 0; i + 2 < positions.count; i += 3) {
    const p = new THREE.Vector3();
    for (let k = 0; k < 3; ++k) p.add(new THREE.Vector3().fromBufferAttribute(positions, i + k));
    p.divideScalar(3).applyMatrix4(object.matrixWorld).project(camera);
    if (Math.abs(p.x) > 0.98 || Math.abs(p.y) > 0.98) continue;
    const x = rect.left + ((p.x + 1) / 2) * rect.width;
    const y = rect.top + ((1 - p.y) / 2) * rect.height;
    const data = pickAt(x, y);
    if (data && sameTarget(data, target)) return { x, y };
  }
  return null;
}
renderer.domElement.addEventListener('pointermove', showHover);
renderer.domElement.addEventListener('pointerleave', () => { $('hover-label').hidden = true; });

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
// The first view: the first colliding step when the run has one, else the first step (step 0).
const collisionPosition = report.collision_step === null ? -1 : steps.findIndex((s) => s.index === report.collision_step);
const openingPosition = collisionPosition >= 0 ? collisionPosition : 0;
showStep(openingPosition);

// Read-only inspection API for tests and curious users: counts and the current step's state.
window.grpvssViewer = Object.freeze({
  counts: Object.freeze({
    linkHulls: built.hullCount,
    obstacles: built.obstacleFills.length,
    links: built.links.length,
    steps: report.steps.length,
    frames: steps.length, // report.steps plus the start configuration (step 0) when drawn
  }),
  openingStep: steps[openingPosition]?.index ?? null,
  /// Page coordinates of a point where `target` ({link, hull} or {obstacle}) is the nearest
  /// object under the pointer at the current step and camera, or null when none is visible.
  visiblePointOf(target) { return visiblePointOf(target); },
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
      hoverShown: $('hover-label').hidden ? null : $('hover-label').textContent,
    };
  },
});
