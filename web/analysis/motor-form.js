// The Analysis tab's motor of your own: its nameplate and lab tests in a form, the equivalent
// circuit the core estimates from them (each value with how it was found, as `imlab motor` prints
// them), and a run of that motor with the design derived from it.
import { $ } from '../ui/page.js';
import { el } from '../ui/dom.js';
import { restReady, t } from '../l10n/l10n.js';
import { sig } from './digits.js';

/** @import { RunClient } from '../client/run-client.js' */
/** @import * as P from '../worker/protocol.js' */

/** The form's fields, named as the core's entry names them. */
const KEYS = /** @type {const} */ (['rs', 'no_load', 'locked', 'nema', 'rated', 'j', 'np']);

/**
 * Wires the motor form: the core reads the fields and names any it refuses; `open(scenario)` runs
 * the motor found.
 * @param {{client: RunClient, open: (scenario: string) => void}} parts
 */
export function createMotorForm({ client, open }) {
  const form = $('motor-form', HTMLFormElement);
  const status = $('motor-status');
  const result = $('motor-result');
  /** @param {string} key */
  const control = (key) => /** @type {HTMLInputElement | HTMLSelectElement} */ (form.elements.namedItem(key));

  /** Fills the form with the example machine's nameplate and readings, as the core writes them. */
  async function example() {
    const unready = await restReady();
    if (unready) return void (status.textContent = unready);
    const entry = await client.job('motor-example', {});
    for (const key of KEYS) control(key).value = entry[key];
    result.replaceChildren();
    status.textContent = t('motor-example-filled');
  }

  /** Asks the core for the circuit of the form's motor and shows it, or what it refused. */
  async function estimate() {
    const unready = await restReady();
    if (unready) return void (status.textContent = unready);
    /** @param {string} key */
    const value = (key) => control(key).value;
    const entry = {
      rs: value('rs'),
      no_load: value('no_load'),
      locked: value('locked'),
      nema: value('nema'),
      rated: value('rated'),
      j: value('j'),
      np: value('np'),
    };
    result.replaceChildren();
    status.textContent = '';
    // The page's state for a reader waiting on it: running, then done or refused.
    document.body.dataset.motor = 'running';
    /** @type {P.Jobs['motor']['result']} */
    let found;
    try {
      found = await client.job('motor', { entry });
    } catch (e) {
      status.textContent = /** @type {Error} */ (e).message;
      document.body.dataset.motor = 'refused';
      return;
    }
    status.textContent = found.heading;
    const items = found.lines.flatMap((line) => [
      el('dt', { textContent: `${line.key} = ${sig(line.value, 4)} ${line.unit}` }),
      el('dd', { textContent: line.rule }),
    ]);
    const run = el('button', { type: 'button', textContent: t('motor-open') });
    run.addEventListener('click', () => open(found.link));
    result.replaceChildren(
      el('dl', { className: 'design-rules' }, items),
      el('p', {}, [run]),
      el('p', {}, [el('code', { className: 'motor-link', textContent: found.link })]),
    );
    document.body.dataset.motor = 'done';
  }

  $('motor-example', HTMLButtonElement).addEventListener('click', example);
  $('motor-run', HTMLButtonElement).addEventListener('click', estimate);
}
