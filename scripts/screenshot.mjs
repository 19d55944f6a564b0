// Writes static/screenshot.png: the app at 1440×900 after running the paper's Fig 3 step preset
// (`?v=1&preset=step`), in headless Debian Chromium. Run `make dist` first, then
// `node scripts/screenshot.mjs`.
import { launch, serve } from '../tests/browser.mjs';

const OUT = new URL('../static/screenshot.png', import.meta.url).pathname;

// The tests' static server for dist/ and their Chromium, with the same flags.
const server = await serve();
const browser = await launch();
try {
  const page = await browser.newPage({ viewport: { width: 1440, height: 900 } });
  const errors = [];
  page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(`${server.url}?v=1&preset=step`);
  // The page runs the scenario in its address on load; wait for that run to be drawn.
  await page.waitForFunction(() => document.body.dataset.state === 'done', null, { timeout: 60_000 });
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => setTimeout(r, 100))));
  if (errors.length) throw new Error(`the page reported errors: ${errors.join('; ')}`);
  await page.screenshot({ path: OUT });
  console.log(`wrote ${OUT}`);
} finally {
  await browser.close();
  server.close();
}
