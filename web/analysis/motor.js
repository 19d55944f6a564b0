// The Analysis tab's motor of your own: its section fetches its form (motor-form.js) and the words
// it needs when first opened, so that the first plot waits for neither.
import { $ } from '../ui/page.js';

/** @import { RunClient } from '../client/run-client.js' */

/**
 * Builds the motor form when its section is first opened; `open(scenario)` runs the motor found.
 * @param {{client: RunClient, open: (scenario: string) => void}} parts
 */
export function wireMotor(parts) {
  const section = $('motor-section', HTMLDetailsElement);
  section.addEventListener(
    'toggle',
    () => import('./motor-form.js').then(({ buildMotorForm }) => buildMotorForm(section, parts)),
    { once: true },
  );
}
