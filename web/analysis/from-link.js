// A tool of the Analysis tab that a shared link holds in its fragment runs once, after the page's
// first run.
import { say } from '../ui/page.js';
import { fragment } from '../ui/url.js';
import { excerpt } from '../ui/quote.js';
import { t } from '../l10n/l10n.js';

/**
 * Reads the fragment `name` now and returns `afterRun()`: the first call fills the tool's form from
 * it (`fill(text)`, which rejects text it cannot take), opens the Analysis tab with
 * `showTab(name)` and starts `run()`; a refused text is said by the message `refused` (of the
 * fragment as `$link` and the reason as `$reason`). Later calls do nothing.
 * @param {{name: string, refused: string, fill: (text: string) => unknown, run: () => unknown,
 *   showTab: (name: string) => void}} tool
 */
export function runFromLink({ name, refused, fill, run, showTab }) {
  let shared = fragment(name); // from the link that opened the page
  return async function afterRun() {
    const text = shared;
    shared = null;
    if (!text) return;
    try {
      await fill(text);
      showTab('analysis');
      run();
    } catch (e) {
      say(t(refused, { link: `#${name}=${excerpt(text)}`, reason: /** @type {Error} */ (e).message }));
    }
  };
}
