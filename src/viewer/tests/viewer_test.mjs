// Browser test of the HTML animation (ctest: viewer_ibm7545_browser). Opens the page written by
// `grpvss verify --html` in headless Debian chromium (playwright-core), checks it against the
// JSON report of the same run, and saves screenshots as test artifacts.
//
// usage: node viewer_test.mjs REPORT.html REPORT.json ARTIFACT_DIR
import { chromium } from 'playwright-core';
import { mkdtempSync, readFileSync, rmSync, mkdirSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const [htmlFile, reportFile, artifactDir] = process.argv.slice(2);
if (!htmlFile || !reportFile || !artifactDir) {
  console.error('usage: node viewer_test.mjs REPORT.html REPORT.json ARTIFACT_DIR');
  process.exit(2);
}
mkdirSync(artifactDir, { recursive: true });
const report = JSON.parse(readFileSync(reportFile, 'utf8'));

let failures = 0;
function check(condition, message) {
  console.log(`${condition ? 'ok  ' : 'FAIL'} ${message}`);
  if (!condition) failures += 1;
}

const userDataDir = mkdtempSync(join(tmpdir(), 'grpvss-viewer-chromium-'));
const context = await chromium.launchPersistentContext(userDataDir, {
  executablePath: process.env.GRPVSS_CHROMIUM || '/usr/bin/chromium',
  headless: true,
  viewport: { width: 1400, height: 860 },
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync',
    // WebGL without a GPU: SwiftShader (software rasterizer shipped with chromium).
    '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
});
try {
  const page = context.pages()[0] ?? await context.newPage();
  const errors = [];
  const remoteRequests = [];
  page.on('pageerror', (error) => errors.push(String(error)));
  page.on('console', (message) => { if (message.type() === 'error') errors.push(message.text()); });
  // The page must work offline: any request that is not the file itself is refused and recorded.
  await page.route('**/*', (route) => {
    const url = route.request().url();
    if (url.startsWith('file:') || url.startsWith('data:') || url.startsWith('blob:')) return route.continue();
    remoteRequests.push(url);
    return route.abort();
  });
  await page.goto(pathToFileURL(resolve(htmlFile)).href);
  await page.waitForFunction(() => window.grpvssViewer !== undefined, null, { timeout: 20000 });

  const counts = await page.evaluate(() => window.grpvssViewer.counts);
  const reportHulls = report.scene.links.reduce((n, link) => n + link.hulls.length, 0);
  check(counts.linkHulls === 11 && reportHulls === 11, `scene holds the robot's 11 hulls (viewer ${counts.linkHulls}, report ${reportHulls})`);
  check(counts.obstacles === 2 && report.scene.obstacles.length === 2, `scene holds the 2 obstacles (viewer ${counts.obstacles})`);
  check(counts.steps === report.steps.length, `viewer has the report's ${report.steps.length} steps`);
  check(counts.links === report.robot.joint_count + 1, `one group per link 0..N (${counts.links})`);

  let state = await page.evaluate(() => window.grpvssViewer.state());
  // The first view is the first colliding step (the IBM 7545 run has one).
  check(report.collision_step !== null && state.step === report.collision_step,
    `opens at the first collision step ${report.collision_step} (at ${state.step})`);
  check(state.verdictShown === report.verdict, `verdict shown "${state.verdictShown}" equals the report's "${report.verdict}"`);
  const digestsShown = await page.locator('#audit-panel').innerText();
  check(['robot', 'environment', 'path'].every((k) => digestsShown.includes(report.inputs[k].sha256)),
    'audit panel shows the three input SHA-256 digests');
  // Clearances are proven lower bounds: shown rounded down, never above the report's number.
  const auditText = await page.locator('#audit-panel').innerText();
  check(typeof report.motion_model === 'string' && auditText.includes(report.motion_model),
    'audit panel states the motion model (the report\'s motion_model)');
  // Every link with hulls is listed, link 0 (the base) included.
  const linksWithHulls = report.scene.links.filter((l) => l.hulls.length > 0).map((l) => l.link);
  check(linksWithHulls.includes(0), 'the IBM 7545 base (link 0) has hulls');
  for (const c of report.link_clearances.filter((l) => linksWithHulls.includes(l.link))) {
    const match = auditText.match(new RegExp(`link ${c.link}\\s+(-?[0-9.]+) at step`));
    const shown = match ? Number(match[1]) : NaN;
    check(shown <= c.min_clearance && c.min_clearance - shown < 1e-4,
      `link ${c.link} clearance shown ${match ? match[1] : '(missing)'} rounds ${c.min_clearance} down`);
  }
  await page.screenshot({ path: join(artifactDir, 'viewer-start.png') });

  // The audit panel lists the report's interference episodes; a row's button shows its first
  // colliding step.
  check(state.episodesShown === report.interference_episodes.length && state.episodesShown > 0,
    `audit panel lists the report's ${report.interference_episodes.length} interference episodes (${state.episodesShown})`);
  const clearedShown = await page.locator('#episodes .cleared').allInnerTexts();
  const cleared = report.interference_episodes.filter((e) => e.cleared_time !== null);
  check(clearedShown.length === cleared.length && cleared.length > 0 &&
      cleared.every((e, i) => clearedShown[i] === `clear by ${e.cleared_time.toFixed(2)} s`),
    `each episode shows the time its pair is clear by (${clearedShown.join('; ')})`);
  const colliding = report.interference_episodes.findIndex((e) => e.first_collision_step !== null);
  check(colliding >= 0, 'the IBM 7545 run has an episode in which the unexpanded robot collides');
  if (colliding >= 0) {
    await page.locator('#episodes button.episode-go').nth(colliding).click();
    const shownAfterClick = (await page.evaluate(() => window.grpvssViewer.state())).step;
    const wanted = report.interference_episodes[colliding].first_collision_step;
    check(shownAfterClick === wanted, `the episode button shows step ${wanted} (at ${shownAfterClick})`);
    await page.screenshot({ path: join(artifactDir, 'viewer-episode.png') });
    await page.click('#first');
  }

  // Step to the first step with interference points with the "next ★" button.
  const firstColliding = report.steps.findIndex((s) => s.interference_points.length > 0);
  check(firstColliding >= 0, `the IBM 7545 run has a step with interference points (index ${firstColliding})`);
  if (firstColliding >= 0) {
    await page.click('#next-interference');
    state = await page.evaluate(() => window.grpvssViewer.state());
    const expected = report.steps[firstColliding];
    check(state.step === expected.index, `"next ★" goes to step ${expected.index} (at ${state.step})`);
    check(state.starsVisible, 'red stars are visible');
    check(state.starCount === expected.interference_points.length,
      `star count ${state.starCount} equals the report's ${expected.interference_points.length}`);
    const shown = Number(await page.locator('#interference-count').innerText());
    check(shown === expected.interference_points.length,
      `interference count shown (${shown}) equals the report's (${expected.interference_points.length})`);
    // The stars must really be drawn: red pixels appear where none are in a star-free frame.
    const redPixels = await page.evaluate(() => {
      const canvas = document.querySelector('#view canvas');
      const g = canvas.getContext('webgl2') || canvas.getContext('webgl');
      const pixels = new Uint8Array(canvas.width * canvas.height * 4);
      g.readPixels(0, 0, canvas.width, canvas.height, g.RGBA, g.UNSIGNED_BYTE, pixels);
      let red = 0;
      for (let i = 0; i < pixels.length; i += 4) {
        if (pixels[i] > 200 && pixels[i + 1] < 60 && pixels[i + 2] < 60) red += 1;
      }
      return red;
    });
    check(redPixels > 20, `red star pixels drawn in the 3-D view (${redPixels})`);
    await page.screenshot({ path: join(artifactDir, 'viewer-interference.png') });
    await page.check('#expanded');
    state = await page.evaluate(() => window.grpvssViewer.state());
    check(state.expandedVisible, 'expanded hulls toggle on');
    await page.screenshot({ path: join(artifactDir, 'viewer-expanded.png') });
    await page.uncheck('#expanded');
    await page.selectOption('#display', 'wireframe');
    await page.screenshot({ path: join(artifactDir, 'viewer-wireframe.png') });
    await page.selectOption('#display', 'both');
  }

  // Step 0 (the start configuration) is reachable: |◀ shows it, → and ← step over it.
  await page.click('#first');
  state = await page.evaluate(() => window.grpvssViewer.state());
  check(state.step === 0 && state.stepIndex === 0, `|◀ shows step 0 (at ${state.step})`);
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('ArrowLeft');
  state = await page.evaluate(() => window.grpvssViewer.state());
  check(state.step === 0, `→ then ← returns to step 0 (at ${state.step})`);

  // Continuous playback from the first step advances the step.
  await page.click('#first');
  await page.selectOption('#speed', '10');
  await page.click('#play');
  await page.waitForFunction((first) => window.grpvssViewer.state().step > first,
    report.steps[0].index, { timeout: 15000 });
  state = await page.evaluate(() => window.grpvssViewer.state());
  check(state.step > report.steps[0].index, `playback advanced to step ${state.step}`);
  await page.click('#play');
  state = await page.evaluate(() => window.grpvssViewer.state());
  check(!state.playing, 'pause stops playback');
  await page.screenshot({ path: join(artifactDir, 'viewer-playback.png') });

  check(remoteRequests.length === 0, `no network requests (${remoteRequests.join(', ') || 'none'})`);
  check(errors.length === 0, `no page errors (${errors.join(' | ') || 'none'})`);
} finally {
  await context.close();
  rmSync(userDataDir, { recursive: true, force: true });
}
console.log(failures === 0 ? 'viewer test passed' : `viewer test: ${failures} failure(s)`);
process.exit(failures === 0 ? 0 : 1);
