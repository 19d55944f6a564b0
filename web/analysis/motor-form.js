// The motor of your own's form, built when its section is first opened: the nameplate and lab
// tests, the equivalent circuit the core estimates from them (each value with how it was found,
// as `imlab motor` prints them), and a run of that motor with the design derived from it.
import { el } from '../ui/dom.js';
import { restReady, t } from '../l10n/l10n.js';
import { sig } from './digits.js';

/** @import { RunClient } from '../client/run-client.js' */
/** @import * as P from '../worker/protocol.js' */

/**
 * The form's fields as the core's entry names them, each with its message and the unit after it.
 * @type {[keyof P.RawJobs['motor']['req']['entry'], string, string][]}
 */
const FIELDS = [
  ['rs', 'motor-rs', 'Ω'],
  ['no_load', 'motor-no-load', 'V,A,W,Hz'],
  ['locked', 'motor-locked', 'V,A,W,Hz'],
  ['nema', 'motor-nema', ''],
  ['rated', 'motor-rated', 'V,Hz,A'],
  ['j', 'motor-j', 'kg m²'],
  ['np', 'motor-np', ''],
];

/**
 * Builds the form in `section` (its words are of the rest of the messages, loaded first; a failed
 * load rejects with why) and wires it: the core reads the fields and names any it refuses; `open(scenario)` runs the motor found.
 * The page's state for a reader waiting on it is `data-motor` on the body: running, then done or
 * refused.
 * @param {HTMLElement} section
 * @param {{client: RunClient, open: (scenario: string) => void}} parts
 */
export async function buildMotorForm(section, { client, open }) {
  const status = el('p', { id: 'motor-status' });
  status.setAttribute('aria-live', 'polite');
  const unready = await restReady();
  if (unready) throw new Error(unready);
  /** @type {Record<string, HTMLInputElement | HTMLSelectElement>} */
  const controls = {};
  const labels = FIELDS.map(([key, message, unit]) => {
    const control =
      key === 'nema'
        ? el(
            'select',
            { name: key },
            ['A', 'B', 'C', 'D'].map((letter) => el('option', { textContent: letter, selected: letter === 'B' })),
          )
        : el('input', { name: key, size: key === 'no_load' || key === 'locked' ? 20 : 8, spellcheck: false });
    controls[key] = control;
    return el('label', {}, [el('span', { textContent: t(message) }), ' ', control, unit ? ` ${unit}` : '']);
  });
  const form = el('form', { id: 'motor-form', className: 'inline-form', autocomplete: 'off' }, labels);
  const estimateButton = el('button', { type: 'button', id: 'motor-run', textContent: t('motor-run-button') });
  const exampleButton = el('button', { type: 'button', id: 'motor-example', textContent: t('motor-example-button') });
  const result = el('div', { id: 'motor-result' });
  section.append(
    el('p', { textContent: t('motor-intro') }),
    form,
    el('div', { className: 'buttons' }, [estimateButton, exampleButton]),
    status,
    result,
  );

  // The last action asked for: an answer to an earlier one is dropped.
  let asked = 0;

  /** Fills the form with the example machine's nameplate and readings, as the core writes them. */
  async function example() {
    const me = ++asked;
    /** @type {P.Jobs['motor-example']['result']} */
    let entry;
    try {
      entry = await client.job('motor-example', {});
    } catch (e) {
      if (me === asked) status.textContent = /** @type {Error} */ (e).message;
      return;
    }
    if (me !== asked) return;
    for (const [key] of FIELDS) controls[key].value = entry[key];
    result.replaceChildren();
    status.textContent = t('motor-example-filled');
  }

  /** Asks the core for the circuit of the form's motor and shows it, or what it refused. */
  async function estimate() {
    /** @param {string} key */
    const value = (key) => controls[key].value;
    const entry = {
      rs: value('rs'),
      no_load: value('no_load'),
      locked: value('locked'),
      nema: value('nema'),
      rated: value('rated'),
      j: value('j'),
      np: value('np'),
    };
    const me = ++asked;
    result.replaceChildren();
    status.textContent = '';
    document.body.dataset.motor = 'running';
    /** @type {P.Jobs['motor']['result']} */
    let found;
    try {
      found = await client.job('motor', { entry });
    } catch (e) {
      if (me !== asked) return;
      status.textContent = /** @type {Error} */ (e).message;
      document.body.dataset.motor = 'refused';
      return;
    }
    if (me !== asked) return;
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

  exampleButton.addEventListener('click', example);
  estimateButton.addEventListener('click', estimate);
  section.dataset.built = '';
}
