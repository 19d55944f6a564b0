// The derived design (design=derived) under the preset's description: each value with the rule
// that gives it and its reason, as the core derives them (`imlab design` prints the same lines).
import { el } from '../ui/dom.js';
import { language, restReady, t } from '../l10n/l10n.js';

/** @import { RunClient } from '../client/run-client.js' */
/** @import * as P from '../worker/protocol.js' */

/**
 * A value of the design to four significant digits in the language shown; a tiny one in
 * scientific notation, as the CLI writes it.
 * @param {number} value
 */
function shown(value) {
  const tiny = value !== 0 && Math.abs(value) < 1e-3;
  /** @type {Intl.NumberFormatOptions} */
  const format = tiny ? { notation: 'scientific', maximumFractionDigits: 3 } : { maximumSignificantDigits: 4 };
  return new Intl.NumberFormat(language, format).format(value).replace('E', 'e').replace(/^-/, '−');
}

/**
 * Shows in `box` the derived design of the scenario `info` describes, or hides `box` when the
 * scenario keeps the paper's design. The design's words are of the rest of the messages, loaded
 * first; an answer for a scenario no longer shown is dropped.
 * @param {RunClient} client
 * @param {HTMLElement} box
 */
export function designView(client, box) {
  let shownFor = '';
  /** @param {string} text */
  const sayInBox = (text) => {
    box.replaceChildren(el('p', { textContent: text }));
    box.hidden = false;
  };
  /** @param {P.Info} info */
  return async (info) => {
    if (info.fields.find((f) => f.key === 'design')?.value !== 'derived') {
      shownFor = '';
      box.hidden = true;
      box.replaceChildren();
      return;
    }
    if (shownFor === info.encoded) return;
    const me = (shownFor = info.encoded);
    const unready = await restReady();
    if (me !== shownFor) return;
    if (unready) return sayInBox(unready);
    /** @type {P.Jobs['design']['result']} */
    let lines;
    try {
      lines = await client.job('design', { scenario: info.encoded });
    } catch (e) {
      if (me === shownFor) sayInBox(t('design-failed', { reason: /** @type {Error} */ (e).message }));
      return;
    }
    if (me !== shownFor) return;
    // A value a line, its rule under it: the sidebar is narrow.
    const items = lines.flatMap((line) => [
      el('dt', { textContent: `${line.key} = ${shown(line.value)} ${line.unit}` }),
      el('dd', { textContent: line.rule }),
    ]);
    box.replaceChildren(
      el('details', {}, [
        el('summary', { textContent: t('design-derived-heading') }),
        el('dl', { className: 'design-rules' }, items),
      ]),
    );
    box.hidden = false;
  };
}
