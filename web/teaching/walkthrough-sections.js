// The walkthrough's sections as the page shows them: each one's prose (its numbers filled in from
// the measurements table), equations, knobs and plots, the lumped-parameter table, and the note
// that the IFOC baseline drives the motor. Their words are messages of the rest
// (walkthrough.ftl), loaded before the sections are built.
import { el } from '../ui/dom.js';
import { language, t, restLoaded } from '../l10n/l10n.js';
import { SECTIONS } from './walkthrough-text.js';
import { laterTex } from './tex.js';
import { scrollBox } from './layout.js';
import { lawBlock } from './law-editor.js';
import { theTable } from './table.js';
import { measuredArgs } from './measured.js';

/** @import * as P from '../worker/protocol.js' */
/** @import { PlotDef } from '../plots/plot-defs.js' */
/** @import { Label, SectionPlot } from './walkthrough-text.js' */

/** @type {Map<string, Record<string, string | number>>} the measurements as variables, by language */
const measurements = new Map();

/**
 * The message `id` of the walkthrough's text with its measurements filled in.
 * @param {string} id
 */
export function measured(id) {
  let args = measurements.get(language);
  if (!args) {
    args = measuredArgs(theTable(), language);
    measurements.set(language, args);
  }
  return t(id, args);
}

/**
 * A number as written in JavaScript (`String`, `toPrecision`), with the decimal separator of the
 * language shown and its digits unchanged: a table's or a report's figure, as exact as the core's.
 * @param {string} text
 */
export function decimal(text) {
  const separator = new Intl.NumberFormat(language).formatToParts(0.5).find((p) => p.type === 'decimal')?.value;
  return separator ? text.replace('.', separator) : text;
}

/**
 * A plot's label as shown: its message, or its symbols. A plot's columns are read before the
 * rest of the messages is in (a run asks for them), its words only once its section is built: until
 * then a message is its id.
 * @param {Label} label
 */
const shownLabel = (label) => (typeof label === 'string' ? label : restLoaded() ? t(label.id, label.args) : label.id);

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
      if (plot) defs.push(plotDef(plot, `${s.id}-${key}`, sectionDivs, s.id));
    }
  }
  return defs;
}

/**
 * The definition of `plot`, plot `id` of section `section`, drawn in the section's box for its
 * plots (`sectionDivs`, by id); its words are read when it is drawn.
 * @param {SectionPlot} plot
 * @param {string} id
 * @param {Record<string, HTMLElement>} sectionDivs
 * @param {string} section
 * @returns {PlotDef}
 */
function plotDef(plot, id, sectionDivs, section) {
  const { title, unit, series, ...rest } = plot;
  return {
    ...rest,
    id,
    get title() {
      return shownLabel({ id: title });
    },
    get unit() {
      return shownLabel(unit);
    },
    get series() {
      return series.map(([column, label, ...more]) => {
        /** @type {import('../plots/plot-defs.js').PlotSeries} */
        const shown = [column, shownLabel(label), ...more];
        return shown;
      });
    },
    get constants() {
      /** @type {NonNullable<PlotDef['constants']>} */
      const lines = plot.nisBand
        ? [[shownLabel({ id: 'walkthrough-nis-low' })], [shownLabel({ id: 'walkthrough-nis-high' })]]
        : plot.bound
          ? [[`+${plot.bound}`], [`−${plot.bound}`]]
          : [];
      return lines;
    },
    // The section's box for its plots, once the sections are built.
    get container() {
      return sectionDivs[section];
    },
    backstepping: BACKSTEPPING.has(section),
  };
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
  const title = t(s.title);
  div.append(el('h2', { textContent: title }));
  for (const p of s.prose) div.append(el('p', { textContent: measured(p) }));
  if (s.figure)
    div.append(
      el('figure', { className: 'diagram' }, [
        scrollBox(
          el('div', { className: 'table-scroll' }, [
            el('img', { src: s.figure.src, alt: t(`${s.figure.text}.alt`), loading: 'lazy', width: 760, height: 300 }),
          ]),
          t('walkthrough-diagram-label', { section: title }),
        ),
        el('figcaption', { textContent: t(s.figure.text) }),
      ]),
    );
  s.equations.forEach((e, i) =>
    div.append(scrollBox(laterTex(e), t('walkthrough-equation-label', { number: i + 1, section: title }))),
  );
  if (s.note) div.append(el('p', { className: 'note', textContent: measured(s.note) }));
  // The numbers a run gives, apart from the derivation they illustrate.
  if (s.shows)
    div.append(
      el('div', { className: 'run-shows' }, [
        el('h3', { textContent: t('walkthrough-run-shows') }),
        ...s.shows.map((p) => el('p', { textContent: measured(p) })),
      ]),
    );
  if (s.lumped) div.append(scrollBox(el('div', { className: 'lumped' }), t('walkthrough-lumped-label')));
  if (s.stability)
    div.append(el('p', { className: 'stability-report', textContent: t('walkthrough-stability-waiting') }));
  if (s.compare) {
    const button = el('button', { type: 'button', className: 'compare', textContent: t('walkthrough-compare-button') });
    button.addEventListener('click', onCompare);
    div.append(button, scrollBox(el('div', { className: 'compare-result' }), t('walkthrough-compare-label')));
  }
  if (s.knobs.length) {
    const knobs = el('div', { className: 'knobs' });
    knobs.dataset.keys = s.knobs.join(' ');
    div.append(el('h3', { textContent: t('walkthrough-knobs') }), knobs);
  }
  if (s.law) div.append(lawBlock(s.law.step, t(s.law.intro)));
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
    note = el('p', { className: 'ifoc-note', textContent: t('walkthrough-ifoc-note') });
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
        el('th', {
          scope: 'row',
          textContent: t(which === 'plant' ? 'walkthrough-lumped-plant' : 'walkthrough-lumped-model'),
        }),
        ...LUMPED.map((k) => {
          const cell = el('td', { textContent: decimal(info[which][k].toPrecision(5)) });
          if (info.plant[k] !== info.model[k]) cell.className = 'differs';
          return cell;
        }),
      ]),
    );
  }
  return table;
}
