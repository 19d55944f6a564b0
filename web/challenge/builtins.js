// The built-in challenges, listed in the Lessons tab: each a link that opens it.
import { el } from '../ui/dom.js';
import { t } from '../l10n/l10n.js';

/** @import { RunClient } from '../client/run-client.js' */

/**
 * Lists the built-in challenges in `list` (the Lessons tab), each a link that opens it; `client`
 * is the page's worker.
 * @param {RunClient} client
 * @param {HTMLElement} list
 */
export async function listBuiltins(client, list) {
  try {
    const builtins = await client.job('challenge-builtins');
    list.replaceChildren(
      ...builtins.map((b) =>
        el('article', { className: 'lesson' }, [
          el('h3', { textContent: b.name }),
          el('p', { textContent: b.summary }),
          el('a', {
            href: `?challenge=${b.name}`,
            textContent: t('builtins-open', { name: b.name }),
            className: 'button-link',
          }),
        ]),
      ),
    );
  } catch {
    list.textContent = t('builtins-failed');
  }
}
