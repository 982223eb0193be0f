// Browser test of the HTML animation of a cell's report (ctest: viewer_sixaxis_browser): the
// six-axis demo cell's collision path (data/sixaxis), whose report names its links and
// obstacles. Checks the first view (the first collision step), names on hover and in the
// panels, step 0 and link 0; saves screenshots as test artifacts.
//
// usage: node viewer_cell_test.mjs REPORT.html REPORT.json ARTIFACT_DIR
import { chromium } from 'playwright-core';
import { mkdtempSync, readFileSync, rmSync, mkdirSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const [htmlFile, reportFile, artifactDir] = process.argv.slice(2);
if (!htmlFile || !reportFile || !artifactDir) {
  console.error('usage: node viewer_cell_test.mjs REPORT.html REPORT.json ARTIFACT_DIR');
  process.exit(2);
}
mkdirSync(artifactDir, { recursive: true });
const report = JSON.parse(readFileSync(reportFile, 'utf8'));

let failures = 0;
function check(condition, message) {
  console.log(`${condition ? 'ok  ' : 'FAIL'} ${message}`);
  if (!condition) failures += 1;
}

const linkNamed = (name) => report.scene.links.find((l) => l.name === name);
const obstacleNamed = (name) => report.scene.obstacles.find((o) => o.name === name);

const userDataDir = mkdtempSync(join(tmpdir(), 'grpvss-viewer-chromium-'));
const context = await chromium.launchPersistentContext(userDataDir, {
  executablePath: process.env.GRPVSS_CHROMIUM || '/usr/bin/chromium',
  headless: true,
  viewport: { width: 1400, height: 860 },
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync',
    '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
});
try {
  const page = context.pages()[0] ?? await context.newPage();
  const errors = [];
  page.on('pageerror', (error) => errors.push(String(error)));
  page.on('console', (message) => { if (message.type() === 'error') errors.push(message.text()); });
  await page.goto(pathToFileURL(resolve(htmlFile)).href);
  await page.waitForFunction(() => window.grpvssViewer !== undefined, null, { timeout: 20000 });
  const viewerState = () => page.evaluate(() => window.grpvssViewer.state());

  // The report is a cell's: names on links, hulls and obstacles.
  const forearm = linkNamed('link_4');
  const post = obstacleNamed('post');
  check(forearm !== undefined && forearm.hulls.length > 0, 'the report names link_4 and it has hulls');
  check(post !== undefined, 'the report names the obstacle post');

  // First view: the first collision step (the first step whose unexpanded robot collides).
  const firstColliding = report.steps.find((s) => s.unexpanded_collides);
  let state = await viewerState();
  check(report.collision_step !== null && firstColliding !== undefined &&
      firstColliding.index === report.collision_step,
    `the report's collision step ${report.collision_step} is its first colliding step`);
  check(state.step === report.collision_step, `opens at the first collision step (at ${state.step})`);
  const opening = await page.evaluate(() => window.grpvssViewer.openingStep);
  check(opening === report.collision_step, `openingStep ${opening}`);
  await page.screenshot({ path: join(artifactDir, 'cell-opening.png') });

  // Hover names what is under the pointer: link_4's hull, then the post.
  const hoverOver = async (target) => {
    const point = await page.evaluate((t) => window.grpvssViewer.visiblePointOf(t), target);
    if (!point) return null;
    await page.mouse.move(point.x, point.y);
    await page.waitForFunction(() => window.grpvssViewer.state().hoverShown !== null, null, { timeout: 5000 });
    return (await viewerState()).hoverShown;
  };
  if (forearm) {
    const shown = await hoverOver({ link: forearm.link, hull: 0 });
    check(shown === `link_4 (link ${forearm.link}), hull 0`, `hover on link_4 shows "${shown}"`);
    check(await page.locator('#hover-label').isVisible(), 'the hover label is visible');
    await page.screenshot({ path: join(artifactDir, 'cell-hover-link.png') });
  }
  if (post) {
    const shown = await hoverOver({ obstacle: post.obstacle });
    check(shown === `post (obstacle ${post.obstacle})`, `hover on the post shows "${shown}"`);
    await page.screenshot({ path: join(artifactDir, 'cell-hover-post.png') });
  }
  await page.mouse.move(5, 5);  // off the 3-D view: the label goes
  state = await viewerState();
  check(state.hoverShown === null, 'leaving the 3-D view hides the hover label');

  // The panels list names: the step's clearances (every link with hulls, link 0 included when
  // it has hulls), the certificate summary and the interference episodes.
  const linksWithHulls = report.scene.links.filter((l) => l.hulls.length > 0);
  const stepRows = await page.locator('#step-clearances tr').allInnerTexts();
  check(stepRows.length === linksWithHulls.length &&
      linksWithHulls.every((l, i) => stepRows[i].startsWith(l.name ? `${l.name} (link ${l.link})` : `link ${l.link}`)),
  `step clearance list names the ${linksWithHulls.length} links with hulls (${stepRows.map((r) => r.split('\t')[0]).join('; ')})`);
  check(report.scene.links[0].hulls.length === 0 || await page.locator('#step-clearances tr[data-link="0"]').count() === 1,
    `link 0 is in the step clearance list when it has hulls (${report.scene.links[0].hulls.length} hulls)`);
  const auditRows = await page.locator('#audit-panel tr[data-link]').allInnerTexts();
  const listed = report.link_clearances.filter((c) => linksWithHulls.some((l) => l.link === c.link));
  check(auditRows.length === listed.length && listed.every((c, i) => auditRows[i].startsWith(
    report.scene.links[c.link].name ? `${report.scene.links[c.link].name} (link ${c.link})` : `link ${c.link}`)),
  `certificate summary lists ${listed.length} links by name`);
  const episodeButtons = await page.locator('#episodes button.episode-go').allInnerTexts();
  check(episodeButtons.length === report.interference_episodes.length && report.interference_episodes.every((e, i) =>
    episodeButtons[i] === `${report.scene.links[e.link].name ?? `link ${e.link}`} hull ${e.hull} / ${report.scene.obstacles[e.obstacle].name ?? `obstacle ${e.obstacle}`}`),
  `episodes named (${episodeButtons.join('; ')})`);
  check(episodeButtons.some((t) => t === 'link_4 hull 0 / post'), 'an episode is link_4 hull 0 / post');

  // Step 0, the start configuration: |◀, the slider and ← reach it.
  await page.click('#first');
  state = await viewerState();
  check(state.step === 0 && state.stepIndex === 0, `|◀ shows step 0 (at ${state.step})`);
  const panel = await page.locator('#step-panel').innerText();
  check(panel.includes('start configuration'), 'the step panel says step 0 is the start configuration');
  await page.screenshot({ path: join(artifactDir, 'cell-step0.png') });
  await page.click('#next');
  state = await viewerState();
  check(state.step === report.steps[0].index, `→ goes to step ${report.steps[0].index} (at ${state.step})`);
  await page.keyboard.press('ArrowLeft');
  state = await viewerState();
  check(state.step === 0, `← returns to step 0 (at ${state.step})`);
  const slide = (value) => page.locator('#timeline-range').evaluate((range, v) => {
    range.value = v;
    range.dispatchEvent(new Event('input', { bubbles: true }));
  }, value);
  await slide('3');
  check(Number(await page.locator('#timeline-range').getAttribute('min')) === 0, 'the slider starts at 0');
  await slide('0');
  state = await viewerState();
  check(state.step === 0, `the slider reaches step 0 (at ${state.step})`);

  check(errors.length === 0, `no page errors (${errors.join(' | ') || 'none'})`);
} finally {
  await context.close();
  rmSync(userDataDir, { recursive: true, force: true });
}
console.log(failures === 0 ? 'viewer cell test passed' : `viewer cell test: ${failures} failure(s)`);
process.exit(failures === 0 ? 0 : 1);
