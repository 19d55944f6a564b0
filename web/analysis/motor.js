// The Analysis tab's motor of your own: its section fetches its form (motor-form.js) and the words
// it needs when first opened, so that the first plot waits for neither.
import { $ } from '../ui/page.js';
import { el } from '../ui/dom.js';

/** @import { RunClient } from '../client/run-client.js' */

/**
 * Builds the motor form when its section is first opened; `open(scenario)` runs the motor found.
 * @param {{client: RunClient, open: (scenario: string) => void}} parts
 */
export function wireMotor(parts) {
  const section = $('motor-section', HTMLDetailsElement);
  /** @type {Promise<void> | null} the form being built, or built; null until opened or after a failed fetch */
  let building = null;
  section.addEventListener('toggle', () => {
    if (building) return;
    section.querySelector('.motor-failed')?.remove();
    building = import('./motor-form.js')
      .then(({ buildMotorForm }) => buildMotorForm(section, parts))
      .catch((e) => {
        // The network gone: said in the section, and fetched again when next opened.
        building = null;
        section.append(el('p', { className: 'motor-failed', textContent: e.message }));
      });
  });
}
