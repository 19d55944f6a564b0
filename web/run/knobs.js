// The walkthrough's knobs: the settings form's controls its sections show for their fields, and
// the edits of them that are checked and run.
import { fieldControl } from './controls.js';

/**
 * Hands out knob controls for the fields of `state.info` that act. A field can be a knob in
 * several sections: the first is `knob-KEY`, later ones `knob-KEY-2`, ... (ids stay unique; the
 * ids given out are counted until `reset()`, once per description).
 */
export function knobMaker(state) {
  const given = new Map(); // knobs given out per field
  return {
    knob(key) {
      const f = state.info?.fields.find((x) => x.key === key && x.value !== null && x.acts);
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

/** Follows the knobs inside `walk`: `changed(control)` takes an edit on change, on Enter, or after a pause in typing. */
export function followKnobs(walk, changed) {
  let timer = null; // a pause in typing in a knob, after which it is checked
  const now = (control) => {
    clearTimeout(timer);
    changed(control);
  };
  walk.addEventListener('change', (e) => e.target.closest('.knobs') && now(e.target));
  walk.addEventListener('keydown', (e) => {
    if (e.key === 'Enter' && e.target.closest('.knobs')) {
      e.preventDefault();
      now(e.target);
    }
  });
  walk.addEventListener('input', (e) => {
    if (!e.target.closest('.knobs') || e.target.type === 'checkbox') return;
    clearTimeout(timer);
    timer = setTimeout(() => now(e.target), 800);
  });
}
