// The design walkthrough: for each of the seven sections its prose, its equations (KaTeX), its
// live signals from the current run and its design knobs; plus the inspect panel and the lessons.
// Every number shown here comes from the core (through the worker); the page only formats it.
import katex from '../../vendor/katex/katex.mjs';
import { Plots, six } from '../plots/plots.js';
import { SECTIONS, STABILITY_CAUSES } from './teaching.js';
import { el } from '../ui/dom.js';

function setAttributes(e, attributes) {
  for (const [name, value] of Object.entries(attributes)) e.setAttribute(name, value);
}

/** A KaTeX-rendered equation (our own TeX, never text from the URL). `label`, if given, is its
 * plain-text name for screen readers (a table header needs one: axe does not read MathML). */
export function tex(source, displayMode = true, label = null) {
  const span = el('span', { className: displayMode ? 'equation' : 'math' });
  typeset(span, source, displayMode);
  if (label) setAttributes(span.querySelector('.katex'), { role: 'math', 'aria-label': label });
  return span;
}

/** Typesets our TeX `source` into `span`. */
function typeset(span, source, displayMode) {
  katex.render(source, span, { displayMode, throwOnError: false, strict: 'ignore' });
}

/** A display equation typeset later, while the page is idle or when the walkthrough is first
 * shown (see `Walkthrough.typesetWhenIdle` and `Walkthrough.shown`): typesetting all of them
 * takes KaTeX longer than anything else at page load. */
function laterTex(source) {
  const span = el('span', { className: 'equation' });
  span.dataset.tex = source;
  return span;
}

/** Typesets an equation made by `laterTex`. */
function typesetWaiting(span) {
  typeset(span, span.dataset.tex, true);
  delete span.dataset.tex;
}

/** A plain-text reading of a short TeX label: "a_1(x_3\\hat x_4 - x_2\\hat x_5)" → "a1(x3x̂4 − x2x̂5)". */
function plain(source) {
  return source
    .replace(/\\hat ([a-z])/g, '$1\u0302')
    .replace(/\\psi/g, 'ψ')
    .replace(/\\omega/g, 'ω')
    .replace(/\\cdot/g, '·')
    .replace(/\\text\{([^}]*)\}/g, '$1')
    .replace(/\\ /g, ' ')
    .replace(/ - /g, ' − ')
    .replace(/[_{}^]/g, '');
}

/**
 * Whether `element` is rendered: not under a hidden tab's panel, which is skipped
 * (`content-visibility`, style.css) where the browser has it and not displayed otherwise.
 */
function rendered(element) {
  return element.checkVisibility?.() ?? element.offsetParent !== null;
}

// A box that scrolls sideways (a long equation, a wide table) must be reachable from the keyboard
// and named; one that fits stays out of the tab order, so the walkthrough does not gain a tab stop
// per equation on a wide screen. Checked whenever a box changes size and when the tab is shown:
// every box is measured before any is marked, so that the page is laid out once, not once a box.
function markScrollable(boxes) {
  const scrolls = boxes.map((box) => box.scrollWidth > box.clientWidth + 1);
  boxes.forEach((box, i) => {
    if (scrolls[i] === (box.getAttribute('role') === 'region')) return;
    if (scrolls[i]) {
      setAttributes(box, { tabindex: '0', role: 'region', 'aria-label': box.dataset.label });
    } else {
      for (const name of ['tabindex', 'role', 'aria-label']) box.removeAttribute(name);
    }
  });
}
const scrollBoxes = new ResizeObserver((entries) => markScrollable(entries.map((e) => e.target)));

/** Registers `box` as a sideways scroll box named `label`. */
function scrollBox(box, label) {
  box.dataset.label = label;
  box.classList.add('scroll-box');
  scrollBoxes.observe(box);
  return box;
}

// Sections whose signals are backstepping terms: with the IFOC baseline they do not drive the motor.
const BACKSTEPPING = new Set(['step1', 'step2', 'step3', 'step4', 'stability']);

/** Plot definitions of every section, each drawn inside its section. */
function plotDefs(sectionDivs) {
  const defs = [];
  for (const s of SECTIONS) {
    for (const plot of [s.plot, s.plot4, s.plot2, s.plot3, s.plot5, s.plot6].filter(Boolean)) {
      const constants = plot.nisBand ? [['2.5 % quantile'], ['97.5 % quantile']] : [];
      defs.push({
        ...plot,
        id: `${s.id}-${defs.length}`,
        constants,
        container: sectionDivs[s.id],
        backstepping: BACKSTEPPING.has(s.id),
      });
    }
  }
  return defs;
}

const LUMPED = ['a1', 'a2', 'a3', 'a5', 'a6', 'a7', 'a8', 'a9', 'a10', 'b'];

// Terms of the inspect panel, grouped by step: [column, TeX label].
const INSPECT = [
  [
    'Step 1',
    [
      ['z1', 'z_1'],
      ['v1', 'v_1'],
      ['v1a', 'v_{1a}'],
      ['v1s', 'v_{1s}'],
      ['torque_hat', 'a_1(x_3\\hat x_4 - x_2\\hat x_5)'],
    ],
  ],
  [
    'Step 2',
    [
      ['z2', 'z_2'],
      ['v2', 'v_2'],
      ['v2a', 'v_{2a}'],
      ['v2s', 'v_{2s}'],
      ['psi2', '\\psi_2'],
    ],
  ],
  [
    'Step 3',
    [
      ['z3', 'z_3'],
      ['v3', 'v_3'],
      ['v3a', 'v_{3a}'],
      ['v3s', 'v_{3s}'],
      ['psi3', '\\psi_3'],
    ],
  ],
  [
    'Step 4',
    [
      ['z4', 'z_4'],
      ['v4', 'v_4'],
      ['v4a', 'v_{4a}'],
      ['v4s', 'v_{4s}'],
      ['psi4', '\\psi_4'],
    ],
  ],
  [
    'Voltage (54) and limit',
    [
      ['u_a_cmd', 'u_1\\ \\text{before}'],
      ['u_b_cmd', 'u_2\\ \\text{before}'],
      ['u_a', 'u_1\\ \\text{applied}'],
      ['u_b', 'u_2\\ \\text{applied}'],
      ['lyapunov', 'V'],
    ],
  ],
  [
    'Estimate x̂ (k|k)',
    [
      ['omega_hat', '\\hat x_1'],
      ['i_sa_hat', '\\hat x_2'],
      ['i_sb_hat', '\\hat x_3'],
      ['phi_ra_hat', '\\hat x_4'],
      ['phi_rb_hat', '\\hat x_5'],
    ],
  ],
  [
    'Measured and true',
    [
      ['y_a', 'y_1'],
      ['y_b', 'y_2'],
      ['omega', 'x_1'],
      ['omega_ref', '\\omega_d'],
    ],
  ],
];

/** Shortest text that reads back as the same double (as the CLI's CSV writes it). */
const exact = (v) => String(v);

/** A column's doc split into its meaning and its unit: "Speed error z1 (rad/s)." → [meaning, unit]. */
function meaningAndUnit(doc) {
  const m = /^(.*?)\s*\(([^()]*)\)\.?$/.exec(doc);
  return m ? [m[1], m[2]] : [doc.replace(/\.$/, ''), ''];
}

export class Walkthrough {
  /**
   * `container` receives the sections, `inspectBox` the inspect panel.
   * `knob(key)` returns the settings control for a field;
   * `onCompare()` asks for the Euler/RK4 comparison.
   */
  constructor({ container, inspectBox, knob, onCompare, onWindow, onFull, onPick, framing }) {
    Object.assign(this, { container, inspectBox, knob });
    inspectBox.setAttribute('aria-labelledby', 'inspect-title');
    // The plot last pressed or focused is the one an inspection comes from (a click, or the arrow
    // keys on a focused plot): the sheet must not cover it.
    this.lastPlot = null;
    const remember = (e) => {
      const plot = e.target instanceof Element ? e.target.closest('.plot') : null;
      if (plot) this.lastPlot = plot;
    };
    document.addEventListener('pointerdown', remember, true);
    document.addEventListener('focusin', remember, true);
    this.sectionDivs = {};
    this.nisBand = [0, 0];
    this.stale = false; // the plots wait for the view of the last run
    this.pending = null; // the last run's whole-run view, drawn when the walkthrough is shown
    this.opened = false; // whether the walkthrough has been shown
    this.typesetting = false; // whether equations are being typeset while the page is idle
    for (const s of SECTIONS) this.container.append(this.section(s, onCompare));
    this.plots = new Plots(container, plotDefs(this.sectionDivs), {
      onWindow,
      onFull,
      onPick,
      framing,
      height: 220,
      constants: (plot) => (plot.nisBand ? this.nisBand : []),
    });
  }

  section(s, onCompare) {
    const div = el('section', { className: 'step', id: `section-${s.id}` });
    div.append(el('h2', { textContent: s.title }));
    for (const p of s.prose) div.append(el('p', { textContent: p }));
    s.equations.forEach((e, i) => div.append(scrollBox(laterTex(e), `Equation ${i + 1} of section ${s.title}`)));
    if (s.note) div.append(el('p', { className: 'note', textContent: s.note }));
    if (s.lumped)
      div.append(scrollBox(el('div', { className: 'lumped' }), 'Lumped parameters of the plant and the model'));
    if (s.stability)
      div.append(
        el('p', { className: 'stability-report', textContent: 'Run a scenario to compare V with the bound.' }),
      );
    if (s.compare) {
      const button = el('button', {
        type: 'button',
        className: 'compare',
        textContent: 'Compare Euler and RK4 predictors on this scenario',
      });
      button.addEventListener('click', onCompare);
      div.append(button, scrollBox(el('div', { className: 'compare-result' }), 'Euler and RK4 predictors compared'));
    }
    const knobs = el('div', { className: 'knobs' });
    knobs.dataset.keys = s.knobs.join(' ');
    div.append(el('h3', { textContent: 'Design knobs' }), knobs);
    const plots = el('div', { className: 'section-plots' });
    div.append(plots);
    this.sectionDivs[s.id] = plots;
    return div;
  }

  /** Shows the knobs (the same controls as the settings form) and the lumped parameters. */
  describe(info) {
    const ifoc = info.fields.find((f) => f.key === 'controller')?.value === 'ifoc';
    this.ifoc = ifoc;
    let note = this.container.querySelector('.ifoc-note');
    if (ifoc && !note) {
      note = el('p', {
        className: 'ifoc-note',
        textContent:
          'This scenario runs the classical IFOC baseline. The backstepping terms below are evaluated from the EKF estimate for comparison; they are not what drives the motor.',
      });
      this.container.prepend(note);
    } else if (!ifoc && note) note.remove();
    // Knobs are rebuilt only when the set of fields that act changes, so an edit keeps its focus
    // and the section does not move.
    for (const box of this.container.querySelectorAll('.knobs')) {
      const knobs = box.dataset.keys
        .split(' ')
        .map((key) => this.knob(key))
        .filter(Boolean);
      const names = (labels) => labels.map((l) => l.querySelector('input, select').name).join();
      const shown = [...box.querySelectorAll('label.field')];
      if (names(knobs) !== names(shown)) {
        box.replaceChildren(...knobs);
        continue;
      }
      knobs.forEach((fresh, i) => {
        const [now, value] = [shown[i].querySelector('input, select'), fresh.querySelector('input, select')];
        now.classList.remove('invalid');
        shown[i].querySelector('.knob-error')?.remove();
        if (now === document.activeElement) return;
        if (now.type === 'checkbox') now.checked = value.checked;
        else now.value = value.value;
      });
    }
    const table = el('table', {}, [
      el('tr', {}, [el('td'), ...LUMPED.map((k) => el('th', { scope: 'col', textContent: k }))]),
    ]);
    for (const which of ['plant', 'model']) {
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
    this.container.querySelector('.lumped').replaceChildren(table);
  }

  /**
   * Takes a finished run's stability report and the NIS band (both from the core). Its plots wait
   * for their view: the run's own when the walkthrough has been opened before, otherwise one the
   * page asks for when it is (until then a run neither computes nor draws them).
   */
  show(stability, nisBand) {
    this.nisBand = nisBand;
    this.stale = true;
    this.pending = null;
    const report = this.container.querySelector('.stability-report');
    report.textContent = stabilityText(stability);
  }

  /** Whether the walkthrough is on screen. */
  visible() {
    return rendered(this.container);
  }

  /** Typesets the equations still waiting a few at a time while the page is idle, so that the
   * walkthrough's first showing need not typeset them all at once; `shown` does what is left. */
  typesetWhenIdle() {
    if (this.typesetting) return;
    // Where the browser lacks idle callbacks: 10 ms slices 50 ms apart.
    const idle =
      globalThis.requestIdleCallback ??
      ((f) =>
        setTimeout(() => {
          const end = performance.now() + 10;
          f({ timeRemaining: () => end - performance.now() });
        }, 50));
    const some = (deadline) => {
      for (const span of this.container.querySelectorAll('.equation[data-tex]')) {
        if (deadline.timeRemaining() <= 0) {
          idle(some);
          return;
        }
        typesetWaiting(span);
      }
      this.typesetting = false;
    };
    this.typesetting = true;
    idle(some);
  }

  /** Whether its plots show the last run (they can take a zoom window then). */
  drawn() {
    return !this.stale && this.pending === null;
  }

  /** The walkthrough has just been shown: its equations are typeset (the first time) and learn
   * whether they scroll, and a waiting view is drawn. */
  shown() {
    this.opened = true;
    for (const span of this.container.querySelectorAll('.equation[data-tex]')) typesetWaiting(span);
    markScrollable([...this.container.querySelectorAll('.scroll-box')]);
    if (this.pending) {
      this.plots.show(this.pending, { ifoc: this.ifoc });
      this.pending = null;
    }
  }

  /**
   * Takes a view of its plots: the first after a run is the whole run, drawn now if the
   * walkthrough is on screen and when it is shown otherwise; later ones are zoom windows.
   */
  receive(view) {
    if (this.stale) {
      this.stale = false;
      if (this.visible()) this.plots.show(view, { ifoc: this.ifoc });
      else this.pending = view;
    } else if (this.pending === null) {
      this.plots.refine(view);
    }
  }

  /** Marks the knob named `key` invalid with the codec's message (null clears every mark). */
  markKnob(key, message) {
    for (const control of this.container.querySelectorAll('.knobs input, .knobs select')) {
      const bad = key !== null && control.name === key;
      control.classList.toggle('invalid', bad);
      control.setAttribute('aria-invalid', bad);
      const label = control.closest('label');
      label.querySelector('.knob-error')?.remove();
      if (bad) label.append(el('span', { className: 'knob-error', role: 'alert', textContent: message }));
    }
  }

  /** Shows every term at one sample: 6 significant digits with units; the exact value in a
   * tooltip and in the copied text. `ts` is the sampling period (s), for rounding t to its sample. */
  inspect(snap, t, ts) {
    const value = Object.fromEntries(snap.columns.map((c, i) => [c, snap.values[i]]));
    const doc = Object.fromEntries(snap.columns.map((c, i) => [c, meaningAndUnit(snap.docs[i])]));
    const box = this.inspectBox;
    const digits = Math.max(0, -Math.floor(Math.log10(ts)) + 1);
    const time = value.t.toFixed(digits).replace(/0+$/, '').replace(/\.$/, '');
    const close = el('button', { type: 'button', className: 'close', textContent: 'Close (Esc)' });
    close.setAttribute('aria-keyshortcuts', 'Escape');
    close.addEventListener('click', () => {
      this.closeInspect();
      if (this.lastPlot && rendered(this.lastPlot)) this.lastPlot.focus({ preventScroll: true });
    });
    const copy = el('button', { type: 'button', className: 'copy', textContent: 'Copy exact values' });
    const lines = snap.columns.map((c) => `${c}\t${exact(value[c])}\t${doc[c][1]}`);
    copy.addEventListener('click', async () => {
      const text = [`k\t${snap.k}`, ...lines].join('\n');
      try {
        await navigator.clipboard.writeText(text);
        copy.textContent = 'Copied';
      } catch {
        copy.textContent = 'Copy failed: select the table instead';
      }
    });
    const title = el('h2', { id: 'inspect-title', textContent: `Inspect sample k = ${snap.k}, t = ${time} s` });
    box.replaceChildren(el('div', { className: 'inspect-head' }, [title, copy, close]));
    box.dataset.t = String(value.t);
    const grid = el('div', { className: 'inspect-grid' });
    const head = () =>
      el(
        'tr',
        {},
        ['term', 'value', 'unit', 'meaning'].map((h) => el('th', { scope: 'col', textContent: h })),
      );
    for (const [title, terms] of INSPECT) {
      const table = el('table', {}, [el('caption', { textContent: title }), head()]);
      for (const [col, label] of terms) {
        const [meaning, unit] = doc[col];
        const cell = el('td', { textContent: six(value[col]), title: `exact: ${exact(value[col])}` });
        cell.dataset.exact = exact(value[col]);
        const row = el('tr', {}, [
          el('th', { scope: 'row' }, [tex(label, false, plain(label))]),
          cell,
          el('td', { className: 'unit', textContent: unit }),
          el('td', { className: 'doc', textContent: meaning }),
        ]);
        row.dataset.column = col;
        table.append(row);
      }
      grid.append(table);
    }
    const gain = el('table', {}, [
      el('caption', { textContent: 'Kalman gain K_k (A⁻¹ × state unit) and L = K_k/Ts (per second)' }),
      el(
        'tr',
        {},
        ['row', 'K·1', 'K·2', 'L·1', 'L·2'].map((h) => el('th', { scope: 'col', textContent: h })),
      ),
    ]);
    snap.gain.forEach((row, i) => {
      gain.append(
        el('tr', {}, [
          el('th', { scope: 'row' }, [tex(`K_{${i + 1}\\cdot}`, false, `K${i + 1}·`)]),
          ...row.map((v) => el('td', { textContent: six(v), title: `exact: ${exact(v)}` })),
          ...snap.l[i].map((v) => el('td', { textContent: six(v), title: `exact: ${exact(v)}` })),
        ]),
      );
    });
    grid.append(gain);
    box.append(grid);
    const opening = box.hidden;
    box.hidden = false;
    if (opening) box.scrollTop = 0;
    this.reveal(this.lastPlot);
    this.onInspect?.(value.t);
  }

  /**
   * Keeps `plot`, the plot the sample was picked on, in view above the sheet: caps the sheet at the
   * room the plot leaves (but not under about ten lines), gives the page that much room at its end,
   * and scrolls the plot into the space above the sheet. If the whole figure cannot fit, its title
   * and canvas do.
   */
  reveal(plot) {
    const box = this.inspectBox;
    box.style.maxHeight = '';
    const visible = plot?.isConnected && rendered(plot);
    const rem = parseFloat(getComputedStyle(document.documentElement).fontSize);
    const gap = 0.5 * rem;
    if (visible) {
      const room = innerHeight - plot.getBoundingClientRect().height - 2 * gap;
      const full = box.offsetHeight;
      if (room < full) box.style.maxHeight = `${Math.max(room, Math.min(full, 10 * rem))}px`;
    }
    const height = box.offsetHeight;
    document.documentElement.style.setProperty('--inspect-height', `${height}px`);
    if (!visible) return;
    const whole = plot.getBoundingClientRect();
    const limit = innerHeight - height - gap;
    const canvas = plot.querySelector('.u-wrap') ?? plot;
    const bottom = whole.height <= limit - gap ? whole.bottom : canvas.getBoundingClientRect().bottom;
    let dy = bottom > limit ? bottom - limit : 0;
    if (whole.top - dy < gap) dy = whole.top - gap;
    if (Math.abs(dy) >= 1) window.scrollBy(0, dy);
  }

  closeInspect() {
    this.inspectBox.hidden = true;
    this.inspectBox.style.maxHeight = '';
    document.documentElement.style.removeProperty('--inspect-height');
    this.onInspect?.(null);
  }

  showComparison(results) {
    const box = this.container.querySelector('.compare-result');
    const rows = [
      [
        'predictor',
        'tracking RMS (rad/s)',
        'speed-estimate RMS (rad/s)',
        'flux-estimate RMS (Wb)',
        'mean NIS',
        'saturated',
      ],
    ];
    for (const r of results) {
      const m = r.metrics;
      rows.push([
        r.predictor,
        m.tracking_rms.toPrecision(3),
        m.speed_estimate_rms.toPrecision(3),
        m.flux_estimate_rms.toPrecision(3),
        m.mean_nis.toPrecision(3),
        `${m.saturated.toPrecision(3)} of samples`,
      ]);
    }
    // The first row names the columns, the first column the predictor.
    const cell = (text, i, j) =>
      i === 0 || j === 0
        ? el('th', { scope: i === 0 ? 'col' : 'row', textContent: text })
        : el('td', { textContent: text });
    const table = el(
      'table',
      {},
      rows.map((r, i) =>
        el(
          'tr',
          {},
          r.map((c, j) => cell(c, i, j)),
        ),
      ),
    );
    box.replaceChildren(
      el('p', {
        textContent: `Same scenario and seed, only the EKF predictor differs; figures from t = ${results[0].metrics.from.toPrecision(3)} s on, the end of the start-up transient, as in the figures strip.`,
      }),
      table,
    );
  }
}

function stabilityText(st) {
  if (!st) return 'Nothing was recorded.';
  const b = st.bound;
  const head = `λ = 2·min(k) = ${b.lambda} 1/s, ε = ${b.eps} (${b.eps ? 'robust terms on' : 'robust terms off, so the bound is V(0)·e^(−λt)'}). `;
  if (st.outside === 0) return `${head}V stays under the bound at all ${st.samples} samples.`;
  const why = STABILITY_CAUSES[st.cause];
  return `${head}V is above the bound at ${st.outside} of ${st.samples} samples, first at t = ${Number(st.first_outside.toPrecision(6))} s; ${st.outside_saturated} of them with the voltage saturated (${st.saturated} samples are saturated in all). ${why}`;
}
