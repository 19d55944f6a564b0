// The preset picker: a preset chosen with the mouse loads at once; one reached with the arrow keys
// loads when it is committed (Enter, or leaving the picker), so stepping through the list starts no
// runs.
import { el } from '../ui/dom.js';

// Keys that move through the preset list without choosing; Enter (also from the open list) chooses.
const BROWSE = new Set(['ArrowUp', 'ArrowDown', 'ArrowLeft', 'ArrowRight', 'Home', 'End', 'PageUp', 'PageDown']);

/**
 * Fills `select` with the core's `presets` ({name, description}).
 * @param {HTMLSelectElement} select
 * @param {{name: string, description: string}[]} presets
 */
export function listPresets(select, presets) {
  for (const p of presets) select.append(el('option', { value: p.name, textContent: p.name }));
}

/**
 * Wires `select` so that `choose(name)` takes each preset committed in it.
 * @param {HTMLSelectElement} select
 * @param {(name: string) => void} choose
 */
export function pickPresets(select, choose) {
  let pending = false; // the picker moved by keyboard, not yet committed
  let byKeyboard = false;

  function commit() {
    pending = false;
    choose(select.value);
  }

  select.addEventListener('keydown', (e) => {
    byKeyboard = BROWSE.has(e.key) || e.key.length === 1;
    if (e.key === 'Enter' && pending) commit();
  });
  select.addEventListener('pointerdown', () => {
    byKeyboard = false;
  });
  select.addEventListener('change', () => {
    pending = true;
    if (!byKeyboard) commit();
  });
  select.addEventListener('blur', () => pending && commit());
}
