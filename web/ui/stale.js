// Results that take a while (the model-error map, the sweep, the seed bands, a challenge's verdict)
// stay on screen when the settings change, and are then of another scenario than the one in the
// settings. Each keeps the scenario it was computed for, as the core encodes it, and is marked as
// an earlier scenario's whenever the settings' encoding (state.info.encoded) is another: the mark
// says what to press to bring it up to date, and clears when the result is run again for the
// settings or when the settings return to its scenario. The core's encoding is canonical, so two
// scenarios are the same exactly when their texts are.
import { el } from './dom.js';
import { excerpt } from './quote.js';
import { t } from '../l10n/l10n.js';

/** @import * as P from '../worker/protocol.js' */

/**
 * A result the page marks while it is of an earlier scenario: its `name` (the body's
 * `data-NAME-stale` is set while it is marked, its mark's id is `NAME-stale`, and the mark says the
 * message `stale-NAME`: what the result is, the button that runs it again, what it means for its
 * export), the element the mark goes before, the elements that show it (outlined while marked) and
 * the buttons that export it without naming its scenario (off while marked).
 * @typedef {{name: string, before: HTMLElement, shows: HTMLElement[], exports?: HTMLButtonElement[],
 *   back?: boolean}} Result
 */

/** How many characters of a result's scenario its mark quotes. */
const QUOTED = 80;

/**
 * The page's record of what its results were computed for. `state.info` is the core's description
 * of the settings (null until the first); `load(scenario)` loads and runs a scenario, for a mark's
 * “Back to its scenario”.
 * @param {{state: {info: P.Info | null}, load: (scenario: string) => unknown}} parts
 */
export function createStale({ state, load }) {
  /** @type {(() => void)[]} */
  const updates = [];

  /**
   * Registers `result`; returns its handle: `ran(scenario)` when it is shown computed for
   * `scenario`, `forget()` when what it shows is no result (a check under way, a refusal).
   * @param {Result} result
   */
  function add(result) {
    const { name, before, shows, exports = [], back = false } = result;
    /** @type {string | null} */
    let scenario = null; // the scenario of the result shown
    const text = el('span');
    const mark = el('p', { id: `${name}-stale`, className: 'warning stale-mark', role: 'status', hidden: true }, [
      text,
    ]);
    if (back) {
      const button = el('button', { type: 'button', textContent: t('stale-back') });
      button.addEventListener('click', () => scenario !== null && load(scenario));
      mark.append(' ', button);
    }

    // In place from the start where `before` is (else once it is), so that a screen reader
    // announces the text the mark is given.
    before.before(mark);

    function update() {
      if (!mark.isConnected) before.before(mark);
      const stale = scenario !== null && state.info !== null && scenario !== state.info.encoded;
      const said = stale ? t(`stale-${name}`, { scenario: excerpt(/** @type {string} */ (scenario), QUOTED) }) : '';
      if (text.textContent !== said) text.textContent = said;
      mark.hidden = !stale;
      for (const e of shows) e.classList.toggle('stale-result', stale);
      if (scenario !== null) for (const b of exports) b.disabled = stale;
      const key = `${name}Stale`;
      if (stale) document.body.dataset[key] = '1';
      else delete document.body.dataset[key];
    }
    updates.push(update);

    return {
      /** @param {string} computedFor */
      ran(computedFor) {
        scenario = computedFor;
        update();
      },
      forget() {
        scenario = null;
        update();
      },
    };
  }

  /** The settings were described anew: each result is marked, or not, against them. */
  function follow() {
    for (const update of updates) update();
  }

  return { add, follow };
}

/** Why an analysis did not run: the settings it would run were refused (`runCurrent`). */
export const NOT_RUN = 'the settings are not valid or not allowed here; the message at the top says why.';
