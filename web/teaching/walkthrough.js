// The design walkthrough: for each of the eight sections its prose, its equations (KaTeX), its
// live signals from the current run and its design knobs; plus the inspect panel and the lessons.
// Every number shown here comes from the core (through the worker); the page only formats it. Its
// words are messages of the rest (walkthrough.ftl, l10n.js), fetched before the sections are built.
import { Plots } from '../plots/plots.js';
import { loadRest, restLoaded, restReady, t } from '../l10n/l10n.js';
import { SECTIONS } from './walkthrough-text.js';
import { loadTable, tableLoaded } from './table.js';
import { typesetWaiting } from './tex.js';
import { keepAboveSheet, markScrollable, rendered } from './layout.js';
import { fillInspect } from './inspect-panel.js';
import { ifocNote, lumpedTable, plotDefs, sectionElement, syncKnobs } from './walkthrough-sections.js';
import { comparison, stabilityText } from './walkthrough-reports.js';
import { fillNames, sayOfTypedLaws, showPreview, showVerdicts } from './law-editor.js';
import { el } from '../ui/dom.js';
import { say } from '../ui/page.js';

export { tex } from './tex.js';

/** @typedef {import('../worker/protocol.js').Jobs} Jobs */
/**
 * A field of the core's description: its key and its value as the codec writes it.
 * @typedef {{key: string, value: string | null}} Field
 */

export class Walkthrough {
  /**
   * `container` receives the sections, `inspectBox` the inspect panel.
   * `knob(key)` returns the settings control for a field;
   * `onCompare()` asks for the Euler/RK4 comparison.
   * @param {{container: HTMLElement, form: HTMLFormElement, inspectBox: HTMLElement, knob: (key: string) => HTMLElement | null,
   *   onCompare: () => void, onWindow: (t0: number, t1: number) => void, onFull: () => void,
   *   onPick: (t: number) => void, framing: () => {fit: boolean, from: number},
   *   preview: (step: number, text: string) => Promise<Jobs['law-preview']['result']>,
   *   language: () => Promise<Jobs['law-language']['result']>}} parts
   */
  constructor({ container, form, inspectBox, knob, onCompare, onWindow, onFull, onPick, framing, preview, language }) {
    this.container = container;
    /** the settings form, whose own-law fields show the verdicts too */
    this.form = form;
    // A verdict says whether it is about the law typed beside it, as it is edited, and the
    // settings' own-law fields show it once their group is built.
    for (const root of [container, form])
      root.addEventListener('input', (e) => {
        if (e.target instanceof HTMLInputElement && e.target.classList.contains('formula'))
          showVerdicts(root, this.verdicts);
      });
    form.addEventListener('fieldsbuilt', () => showVerdicts(form, this.verdicts));
    this.inspectBox = inspectBox;
    this.knob = knob;
    /** @type {((t: number | null) => void) | null} told of each inspected time (null: the panel closed) */
    this.onInspect = null;
    inspectBox.setAttribute('aria-labelledby', 'inspect-title');
    // The plot last pressed or focused is the one an inspection comes from (a click, or the arrow
    // keys on a focused plot): the sheet must not cover it.
    /** @type {HTMLElement | null} */
    this.lastPlot = null;
    /** @param {Event} e */
    const remember = (e) => {
      const plot = e.target instanceof Element ? /** @type {HTMLElement | null} */ (e.target.closest('.plot')) : null;
      if (plot) this.lastPlot = plot;
    };
    document.addEventListener('pointerdown', remember, true);
    document.addEventListener('focusin', remember, true);
    /** @type {Record<string, HTMLElement>} each section's box for its plots, by the section's id */
    this.sectionDivs = {};
    /** @type {number[]} the NIS band, from the core */
    this.nisBand = [0, 0];
    /** @type {import('../worker/protocol.js').Info | null} the core's description of the scenario shown */
    this.info = null;
    this.stale = false; // the plots wait for the view of the last run
    /** @type {import('../worker/protocol.js').View | null} the last run's view, drawn when the walkthrough is shown */
    this.pending = null;
    this.opened = false; // whether the walkthrough has been shown
    this.onCompare = onCompare;
    /** @type {import('../worker/protocol.js').Done['stability'] | undefined} the last run's stability report */
    this.stability = undefined;
    /** @type {Promise<boolean> | null} the sections being built (whether they were) */
    this.building = null;
    /** @type {(() => void) | null} told when the sections are built */
    this.onBuilt = null;
    /** @type {() => Promise<Jobs['law-language']['result']>} asks for the language of the steps' own laws */
    this.language = language;
    /** @type {Promise<void> | null} the language's names listed in each step, once asked for */
    this.named = null;
    /** @type {Jobs['law-verdicts']['result']} the verdicts on the own laws of the last run */
    this.verdicts = [];
    // A step's own law is typeset by the core as it is typed, a moment after the last key.
    /** @type {(step: number, text: string) => Promise<Jobs['law-preview']['result']>} */
    this.preview = preview;
    /** @type {ReturnType<typeof setTimeout> | undefined} */
    let typing;
    container.addEventListener('input', (e) => {
      const input = e.target instanceof HTMLInputElement ? e.target : null;
      if (!input?.matches('.law .formula')) return;
      clearTimeout(typing);
      typing = setTimeout(() => this.previewLaw(input), 150);
    });
    this.plots = new Plots(container, plotDefs(this.sectionDivs), {
      onWindow,
      onFull,
      onPick,
      framing,
      height: 220,
      constants: (plot) => (plot.nisBand ? this.nisBand : plot.bound ? this.bound(plot.bound) : []),
    });
  }

  /**
   * ±`key` (h2 or h4) of the scenario described last: the bound the robust term assumes.
   * @param {string} key
   */
  bound(key) {
    const h = Number(this.info?.fields.find((/** @type {Field} */ f) => f.key === key)?.value ?? 0);
    return [h, -h];
  }

  /** Whether the sections are built. */
  built() {
    return this.container.childElementCount > 0;
  }

  /**
   * Builds the sections, once: when the walkthrough is first shown or the page is idle after the
   * first run is drawn, whichever comes first (the first plot does not wait for them), once their
   * texts are in. They take the last description and stability report. Resolves to whether they
   * are built: when their texts could not be fetched, the next call tries again.
   * @returns {Promise<boolean>}
   */
  build() {
    this.building ??= Promise.all([loadRest(), loadTable()]).then(
      () => {
        this.buildSections();
        return true;
      },
      () => {
        this.building = null;
        return false;
      },
    );
    return this.building;
  }

  /** Builds the sections in the container, once; their texts are in. */
  buildSections() {
    if (this.built()) return;
    for (const s of SECTIONS) {
      const [section, plots] = sectionElement(s, this.onCompare);
      this.sectionDivs[s.id] = plots;
      this.container.append(section);
    }
    if (this.info) this.describe(this.info);
    this.showReport();
    showVerdicts(this.container, this.verdicts);
    this.onBuilt?.();
  }

  /** Writes the last run's stability report in its section, once built and a run has ended. */
  showReport() {
    const report = this.container.querySelector('.stability-report');
    if (report && this.stability !== undefined) report.textContent = stabilityText(this.stability);
  }

  /**
   * Lists in each step the names its own law may use, once: they come with the core built with
   * its tools, fetched when the walkthrough is first shown (with KaTeX, for their symbols).
   */
  listNames() {
    this.named ??= this.language().then(
      (language) => fillNames(this.container, language),
      () => {
        this.named = null; // asked again when the walkthrough is next shown
      },
    );
  }

  /**
   * Shows each step's verdict on the own law of the run shown (the core's).
   * @param {Jobs['law-verdicts']['result']} verdicts
   */
  showVerdicts(verdicts) {
    this.verdicts = verdicts;
    for (const root of this.lawRoots()) showVerdicts(root, verdicts);
  }

  /**
   * Says in each step with its own law that the verdicts could not be computed, and why: `failure`
   * is what the job was refused with (why a law or the scenario was refused, said already).
   * @param {unknown} failure
   */
  verdictsFailed(failure) {
    const reason = failure instanceof Error ? failure.message : String(failure);
    for (const root of this.lawRoots()) sayOfTypedLaws(root, t('law-verdict-failed', { reason }));
  }

  /** Where verdicts are shown: the steps here, and the settings form's own-law fields. */
  lawRoots() {
    return [this.container, this.form];
  }

  /**
   * Shows the core's preview of the law in the knob `input`, unless it changed meanwhile.
   * @param {HTMLInputElement} input
   */
  async previewLaw(input) {
    const box = /** @type {HTMLElement} */ (input.closest('.law'));
    const text = input.value;
    const preview = await this.preview(Number(box.dataset.step), text).catch(() => null);
    if (preview && input.value === text) showPreview(box, preview, text);
  }

  /**
   * Shows the knobs (the same controls as the settings form) and the lumped parameters.
   * @param {import('../worker/protocol.js').Info} info
   */
  describe(info) {
    this.info = info;
    const ifoc = info.fields.find((/** @type {Field} */ f) => f.key === 'controller')?.value === 'ifoc';
    this.ifoc = ifoc;
    if (!this.built()) return;
    ifocNote(this.container, ifoc);
    syncKnobs(this.container, (key) => this.knob(key));
    /** @type {Element} */ (this.container.querySelector('.lumped')).replaceChildren(lumpedTable(info));
    if (this.opened) this.previewLaws();
  }

  /** Typesets each step's own law (KaTeX is fetched when the walkthrough is first shown). */
  previewLaws() {
    const inputs = /** @type {NodeListOf<HTMLInputElement>} */ (this.container.querySelectorAll('.law .formula'));
    for (const input of inputs) this.previewLaw(input);
  }

  /**
   * Takes a finished run's stability report and the NIS band (both from the core). Its plots wait
   * for their view: the run's own when the walkthrough has been opened before, otherwise one the
   * page asks for when it is (until then a run neither computes nor draws them).
   * @param {import('../worker/protocol.js').Done['stability']} stability
   * @param {number[]} nisBand
   */
  show(stability, nisBand) {
    this.nisBand = nisBand;
    this.stale = true;
    this.pending = null;
    this.stability = stability;
    this.showReport();
  }

  /**
   * A run ended: without own laws each step says it runs the paper's; with them, the steps with
   * a law say it is being checked until the verdicts come (`showVerdicts`).
   * @param {boolean} checking
   */
  checkingLaws(checking) {
    this.showVerdicts([]);
    if (!checking) return;
    for (const root of this.lawRoots()) sayOfTypedLaws(root, t('law-checking'));
  }

  /** Whether the walkthrough is on screen. */
  visible() {
    return rendered(this.container);
  }

  /** Whether its plots show the last run (they can take a zoom window then). */
  drawn() {
    return !this.stale && this.pending === null;
  }

  /** The walkthrough has just been shown: once its sections are built, its equations are typeset
   * (the first time) and learn whether they scroll, and a waiting view is drawn. Should its texts
   * fail to load (the network gone), the page says so. */
  shown() {
    if (restLoaded() && tableLoaded()) this.buildSections();
    this.build().then((built) => (built ? this.opening() : say(t('walkthrough-load-failed'))));
  }

  /** The walkthrough is shown with its sections built. */
  opening() {
    if (!this.opened) this.previewLaws();
    this.listNames();
    this.opened = true;
    // The equations are typeset once KaTeX is in (fetched now the first time): then they learn
    // whether they scroll. Should KaTeX fail to load (the network gone), the page says so.
    typesetWaiting(this.container).then(
      () =>
        markScrollable([.../** @type {NodeListOf<HTMLElement>} */ (this.container.querySelectorAll('.scroll-box'))]),
      () => say(t('walkthrough-equations-failed')),
    );
    if (this.pending && this.visible()) {
      this.plots.show(this.pending, { ifoc: this.ifoc });
      this.pending = null;
    }
  }

  /**
   * Takes a view of its plots: the first after a run is the whole run, drawn now if the
   * walkthrough is on screen and when it is shown otherwise; later ones are zoom windows.
   * @param {import('../worker/protocol.js').View} view
   */
  receive(view) {
    if (this.stale) {
      this.stale = false;
      if (this.visible() && this.built()) this.plots.show(view, { ifoc: this.ifoc });
      else this.pending = view;
    } else if (this.pending === null) {
      this.plots.refine(view);
    }
  }

  /**
   * Marks the knob named `key` invalid with the codec's message (null clears every mark).
   * @param {string | null} key
   * @param {string} [message]
   */
  markKnob(key, message) {
    const controls = /** @type {NodeListOf<HTMLInputElement | HTMLSelectElement>} */ (
      this.container.querySelectorAll('.knobs input, .knobs select')
    );
    for (const control of controls) {
      const bad = key !== null && control.name === key;
      control.classList.toggle('invalid', bad);
      control.setAttribute('aria-invalid', String(bad));
      // Every knob's control is inside its label.
      const label = /** @type {HTMLLabelElement} */ (control.closest('label'));
      label.querySelector('.knob-error')?.remove();
      if (bad) label.append(el('span', { className: 'knob-error', role: 'alert', textContent: message }));
    }
  }

  /** Shows every term at one sample: 6 significant digits with units; the exact value in a
   * tooltip and in the copied text. `ts` is the sampling period (s), for rounding t to its sample.
   * The panel's words are of the rest of the messages, loaded first.
   * @param {import('../worker/protocol.js').Inspected['snapshot']} snap
   * @param {number} time
   * @param {number} ts
   */
  async inspect(snap, time, ts) {
    const unready = await restReady();
    if (unready) say(unready);
    else this.showInspect(snap, time, ts);
  }

  /**
   * The inspect panel for `snap`, once the rest of the messages is loaded.
   * @param {import('../worker/protocol.js').Inspected['snapshot']} snap
   * @param {number} t
   * @param {number} ts
   */
  showInspect(snap, t, ts) {
    const box = this.inspectBox;
    const time = fillInspect(box, snap, ts, () => {
      this.closeInspect();
      if (this.lastPlot && rendered(this.lastPlot)) this.lastPlot.focus({ preventScroll: true });
    });
    const opening = box.hidden;
    box.hidden = false;
    if (opening) box.scrollTop = 0;
    this.reveal(this.lastPlot);
    this.onInspect?.(time);
  }

  /**
   * Keeps `plot`, the plot the sample was picked on, in view above the inspect sheet.
   * @param {HTMLElement | null} plot
   */
  reveal(plot) {
    keepAboveSheet(this.inspectBox, plot);
  }

  closeInspect() {
    this.inspectBox.hidden = true;
    this.inspectBox.style.maxHeight = '';
    document.documentElement.style.removeProperty('--inspect-height');
    this.onInspect?.(null);
  }

  /** @param {import('../worker/protocol.js').Compared['results']} results */
  showComparison(results) {
    /** @type {Element} */ (this.container.querySelector('.compare-result')).replaceChildren(...comparison(results));
  }
}
