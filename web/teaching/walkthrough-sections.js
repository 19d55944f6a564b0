// The walkthrough's sections as the page shows them: each one's prose (its numbers filled in from
// the measurements table), equations, knobs and plots, the lumped-parameter table, and the note
// that the IFOC baseline drives the motor.
import { el } from '../ui/dom.js';
import { SECTIONS } from './walkthrough-text.js';
import { laterTex } from './tex.js';
import { scrollBox } from './layout.js';
import { lawBlock } from './law-editor.js';
import { TABLE } from './table.js';
import { render } from './measured.js';

/** @import * as P from '../worker/protocol.js' */
/** @import { PlotDef } from '../plots/plot-defs.js' */

/**
 * A template of the walkthrough's text with its measurements filled in.
 * @param {string} template
 */
const measured = (template) => render(template, TABLE);

// Sections whose signals are backstepping terms: with the IFOC baseline they do not drive the motor.
const BACKSTEPPING = new Set(['step1', 'step2', 'step3', 'step4', 'stability']);

/**
 * Plot definitions of every section, each drawn inside its section (`sectionDivs`, by id).
 * @param {Record<string, HTMLElement>} sectionDivs
 */
export function plotDefs(sectionDivs) {
  /** @type {PlotDef[]} */
  const defs = [];
  for (const s of SECTIONS) {
    // Each plot's id is its section's and its key's (`ekf-plot4`, `step1-law`): a lesson names it.
    const plots = /** @type {const} */ ([
      ['plot', s.plot],
      ['plot4', s.plot4],
      ['plot2', s.plot2],
      ['plot3', s.plot3],
      ['plot5', s.plot5],
      ['plot6', s.plot6],
      ['law', s.law?.plot],
    ]);
    for (const [key, plot] of plots) {
      if (!plot) continue;
      /** @type {PlotDef['constants']} */
      const constants = plot.nisBand
        ? [['2.5 % quantile'], ['97.5 % quantile']]
        : plot.bound
          ? [[`+${plot.bound}`], [`−${plot.bound}`]]
          : [];
      defs.push({
        ...plot,
        id: `${s.id}-${key}`,
        constants,
        // The section's box for its plots, once the sections are built.
        get container() {
          return sectionDivs[s.id];
        },
        backstepping: BACKSTEPPING.has(s.id),
      });
    }
  }
  return defs;
}

/**
 * Section `s` of SECTIONS: its prose, equations (typeset later), the boxes its results fill, its
 * knobs and the box its plots go in. `onCompare()` asks for the Euler/RK4 comparison. Returns
 * [the section, the box for its plots].
 * @param {import('./walkthrough-text.js').Section} s
 * @param {() => void} onCompare
 * @returns {[HTMLElement, HTMLDivElement]}
 */
export function sectionElement(s, onCompare) {
  const div = el('section', { className: 'step', id: `section-${s.id}` });
  div.append(el('h2', { textContent: s.title }));
  for (const p of s.prose) div.append(el('p', { textContent: measured(p) }));
  if (s.figure)
    div.append(
      el('figure', { className: 'diagram' }, [
        scrollBox(
          el('div', { className: 'table-scroll' }, [
            el('img', { src: s.figure.src, alt: s.figure.alt, loading: 'lazy', width: 760, height: 300 }),
          ]),
          `Diagram of section ${s.title}`,
        ),
        el('figcaption', { textContent: s.figure.caption }),
      ]),
    );
  s.equations.forEach((e, i) => div.append(scrollBox(laterTex(e), `Equation ${i + 1} of section ${s.title}`)));
  if (s.note) div.append(el('p', { className: 'note', textContent: measured(s.note) }));
  // The numbers a run gives, apart from the derivation they illustrate.
  if (s.shows)
    div.append(
      el('div', { className: 'run-shows' }, [
        el('h3', { textContent: 'What the run shows' }),
        ...s.shows.map((p) => el('p', { textContent: measured(p) })),
      ]),
    );
  if (s.lumped)
    div.append(scrollBox(el('div', { className: 'lumped' }), 'Lumped parameters of the plant and the model'));
  if (s.stability)
    div.append(el('p', { className: 'stability-report', textContent: 'Run a scenario to compare V with the bound.' }));
  if (s.compare) {
    const button = el('button', {
      type: 'button',
      className: 'compare',
      textContent: 'Compare Euler and RK4 predictors on this scenario',
    });
    button.addEventListener('click', onCompare);
    div.append(button, scrollBox(el('div', { className: 'compare-result' }), 'Euler and RK4 predictors compared'));
  }
  if (s.knobs.length) {
    const knobs = el('div', { className: 'knobs' });
    knobs.dataset.keys = s.knobs.join(' ');
    div.append(el('h3', { textContent: 'Design knobs' }), knobs);
  }
  if (s.law) div.append(lawBlock(s.law));
  const plots = el('div', { className: 'section-plots' });
  div.append(plots);
  return [div, plots];
}

/**
 * Shows, atop `container`, that the IFOC baseline drives the motor when `ifoc`; removes it otherwise.
 * @param {HTMLElement} container
 * @param {boolean} ifoc
 */
export function ifocNote(container, ifoc) {
  let note = container.querySelector('.ifoc-note');
  if (ifoc && !note) {
    note = el('p', {
      className: 'ifoc-note',
      textContent:
        'This scenario runs the classical IFOC baseline. The backstepping terms below are evaluated from the EKF estimate for comparison; they are not what drives the motor.',
    });
    container.prepend(note);
  } else if (!ifoc && note) note.remove();
}

/**
 * Fills each section's knobs in `container` with `knob(key)`, the settings control of a field.
 * Knobs are rebuilt only when the set of fields that act changes, so an edit keeps its focus and
 * the section does not move; otherwise they take the new values and lose their error marks.
 * @param {HTMLElement} container
 * @param {(key: string) => HTMLElement | null} knob
 */
export function syncKnobs(container, knob) {
  for (const box of /** @type {NodeListOf<HTMLElement>} */ (container.querySelectorAll('.knobs'))) {
    // Every knobs box names its fields; a knob is a label that holds its control.
    const knobs = /** @type {HTMLElement[]} */ (
      /** @type {string} */ (box.dataset.keys)
        .split(' ')
        .map((key) => knob(key))
        .filter(Boolean)
    );
    /** @param {Element} label */
    const control = (label) =>
      /** @type {HTMLInputElement | HTMLSelectElement} */ (label.querySelector('input, select'));
    /** @param {Element[]} labels */
    const names = (labels) => labels.map((l) => control(l).name).join();
    const shown = [...box.querySelectorAll('label.field')];
    if (names(knobs) !== names(shown)) {
      box.replaceChildren(...knobs);
      continue;
    }
    knobs.forEach((fresh, i) => {
      const [now, value] = [control(shown[i]), control(fresh)];
      now.classList.remove('invalid');
      shown[i].querySelector('.knob-error')?.remove();
      if (now === document.activeElement) return;
      // Both are the same field's control: a checkbox is an input in each.
      if (now.type === 'checkbox')
        /** @type {HTMLInputElement} */ (now).checked = /** @type {HTMLInputElement} */ (value).checked;
      else now.value = value.value;
    });
  }
}

/** @type {(keyof P.Info['plant'])[]} */
const LUMPED = ['a1', 'a2', 'a3', 'a5', 'a6', 'a7', 'a8', 'a9', 'a10', 'b'];

/**
 * The lumped parameters of the plant and the model (`info`, the core's description), those that differ marked.
 * @param {P.Info} info
 */
export function lumpedTable(info) {
  const table = el('table', {}, [
    el('tr', {}, [el('td'), ...LUMPED.map((k) => el('th', { scope: 'col', textContent: k }))]),
  ]);
  for (const which of /** @type {const} */ (['plant', 'model'])) {
    table.append(
      el('tr', {}, [
        el('th', { scope: 'row', textContent: which }),
        ...LUMPED.map((k) => {
          const cell = el('td', { textContent: info[which][k].toPrecision(5) });
          if (info.plant[k] !== info.model[k]) cell.className = 'differs';
          return cell;
        }),
      ]),
    );
  }
  return table;
}
