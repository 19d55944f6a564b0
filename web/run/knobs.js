// The walkthrough's knobs: the settings form's controls its sections show for their fields, and
// the edits of them that are checked and run.
import { fieldControl } from './controls.js';

/** @import { State } from '../main.js' */

/**
 * A knob's control: the input or select of its field (controls.js).
 * @typedef {HTMLInputElement | HTMLSelectElement} Control
 */

/**
 * Hands out knob controls for the fields of `state.info` that act. A field can be a knob in
 * several sections: the first is `knob-KEY`, later ones `knob-KEY-2`, ... (ids stay unique; the
 * ids given out are counted until `reset()`, once per description).
 * @param {State} state
 */
export function knobMaker(state) {
  /** @type {Map<string, number>} */
  const given = new Map(); // knobs given out per field
  return {
    /** @param {string} key */
    knob(key) {
      const f = state.info?.fields.find(
        (/** @type {{key: string, value: string | null, acts: boolean}} */ x) =>
          x.key === key && x.value !== null && x.acts,
      );
      if (!f) return null;
      const n = (given.get(key) ?? 0) + 1;
      given.set(key, n);
      return fieldControl(f, n === 1 ? 'knob' : `knob${n}`);
    },
    reset() {
      given.clear();
    },
  };
}

/**
 * Follows the knobs inside `walk`: `changed(control)` takes an edit on change, on Enter, or after a pause in typing.
 * @param {HTMLElement} walk
 * @param {(control: Control) => void} changed
 */
export function followKnobs(walk, changed) {
  /** @type {number | undefined} */
  let timer; // a pause in typing in a knob, after which it is checked
  /** @param {Control} control */
  const now = (control) => {
    clearTimeout(timer);
    changed(control);
  };
  // The element an event in `walk` came from: a knob's control when it is inside `.knobs`.
  const from = (/** @type {Event} */ e) => /** @type {Control} */ (e.target);
  walk.addEventListener('change', (e) => from(e).closest('.knobs') && now(from(e)));
  walk.addEventListener('keydown', (e) => {
    if (e.key === 'Enter' && from(e).closest('.knobs')) {
      e.preventDefault();
      now(from(e));
    }
  });
  walk.addEventListener('input', (e) => {
    if (!from(e).closest('.knobs') || from(e).type === 'checkbox') return;
    clearTimeout(timer);
    timer = setTimeout(() => now(from(e)), 800);
  });
}
