// Guided lessons: a list in the Lessons tab, and a lesson panel beside the plots that keeps the
// lesson's context (what to look for, the question, a hint, the answer) while its plots are shown.
import { el } from '../ui/dom.js';
import { keepWhole } from './layout.js';

/** @typedef {import('./teaching.js').Lesson} Lesson */

/**
 * The link to `lesson`: its run, and its name, which opens its panel.
 * @param {Lesson} lesson
 */
export const lessonLink = (lesson) => `${location.origin}${location.pathname}?${lesson.run}#lesson=${lesson.id}`;

/**
 * Copies the link to `lesson`, saying so in `said` (or showing the link where the clipboard is refused).
 * @param {Lesson} lesson
 * @param {HTMLElement} said
 */
async function copyLink(lesson, said) {
  const link = lessonLink(lesson);
  try {
    await navigator.clipboard.writeText(link);
    said.textContent = 'Link copied: it opens this lesson and its run.';
  } catch {
    said.textContent = `Copy this link: ${link}`;
  }
}

export class LessonPanel {
  /**
   * `panel` receives the open lesson, `list` the lesson cards. `onOpen(lesson)` loads and runs the
   * lesson's run (a scenario string); `draw(plot)` draws a plot's chart that waits to come into view.
   * @param {{panel: HTMLElement, list: HTMLElement, lessons: Lesson[],
   *   onOpen: (lesson: Lesson) => Promise<void>, draw: (plot: HTMLElement) => void}} parts
   */
  constructor({ panel, list, lessons, onOpen, draw }) {
    this.panel = panel;
    this.lessons = lessons;
    this.onOpen = onOpen;
    this.draw = draw;
    /** @type {number | null} the lesson open, by its place in `lessons` */
    this.index = null;
    this.ran = false; // whether the open lesson's run has been drawn
    lessons.forEach((lesson, i) => {
      const start = el('button', { type: 'button', textContent: `Start lesson ${i + 1}` });
      start.dataset.lesson = lesson.run;
      start.addEventListener('click', () => this.open(i));
      list.append(
        el('article', { className: 'lesson' }, [
          el('h3', { textContent: `${i + 1}. ${lesson.title}` }),
          el('p', { textContent: lesson.look }),
          el('p', { className: 'question', textContent: `Question: ${lesson.question}` }),
          start,
        ]),
      );
    });
  }

  /**
   * Opens lesson `i`: shows its panel, scrolled to the top, with focus on its title, and runs it.
   * @param {number} i
   */
  async open(i) {
    this.index = i;
    const lesson = this.lessons[i];
    const previous = el('button', { type: 'button', textContent: '← Previous', disabled: i === 0 });
    const next = el('button', { type: 'button', textContent: 'Next →', disabled: i === this.lessons.length - 1 });
    const close = el('button', { type: 'button', className: 'close', textContent: 'Close lesson' });
    const copy = el('button', { type: 'button', className: 'copy-lesson', textContent: 'Copy link to this lesson' });
    const copied = el('p', { className: 'hint', role: 'status' });
    copy.addEventListener('click', () => copyLink(lesson, copied));
    previous.addEventListener('click', () => this.open(i - 1));
    next.addEventListener('click', () => this.open(i + 1));
    close.addEventListener('click', () => this.close());
    const hint = el('details', { className: 'hint' }, [
      el('summary', { textContent: 'Hint' }),
      el('p', { textContent: lesson.hint }),
    ]);
    const answer = el('details', { className: 'answer' }, [
      el('summary', { textContent: 'Show answer (for the lecturer)' }),
      el('p', { textContent: lesson.answer }),
    ]);
    // The parts in reading order; presentation mode (style) puts the question under the title
    // and lets what to look for, the hint and the answer scroll in their own boxes below it.
    this.panel.replaceChildren(
      close,
      el('p', { className: 'lesson-count' }, [
        `Lesson ${i + 1} of ${this.lessons.length}`,
        el('span', { className: 'lesson-run', textContent: ` · run ${lesson.run}` }),
      ]),
      el('h2', { textContent: lesson.title, tabIndex: -1 }),
      el('div', { className: 'lesson-look' }, [
        el('h3', { textContent: 'What to look for' }),
        el('p', { className: 'look', textContent: lesson.look }),
      ]),
      el('div', { className: 'lesson-question' }, [
        el('h3', { className: 'question-head', textContent: 'Question' }),
        el('p', { className: 'question', textContent: lesson.question }),
      ]),
      el('div', { className: 'lesson-more' }, [hint, answer]),
      el('div', { className: 'buttons' }, [previous, next, copy]),
      copied,
    );
    this.panel.dataset.open = lesson.run;
    delete this.panel.dataset.shown;
    this.ran = false;
    this.panel.hidden = false;
    this.panel.scrollTop = 0;
    document.body.classList.add('with-lesson');
    // Keyboard and screen-reader users continue where the content is, not at the page's top.
    const started = this.onOpen(lesson);
    /** @type {HTMLHeadingElement} */ (this.panel.querySelector('h2')).focus({ preventScroll: true });
    this.showPlot();
    await started;
  }

  /** The open lesson's run has been drawn: its plot is shown. */
  afterRun() {
    if (this.index === null || this.ran) return;
    this.ran = true;
    this.showPlot();
  }

  /**
   * Marks the plot the open lesson's question is about (`lesson-plot`: presentation mode puts it
   * first among the Trajectories plots) and, once the lesson's run is drawn, in presentation mode
   * with the lesson beside the results, brings it whole into view; the panel's `data-shown` then
   * names the lesson. Called again when a plot is drawn anew (the lesson's map).
   */
  showPlot() {
    const lesson = this.index === null ? null : this.lessons[this.index];
    const plot = lesson && document.querySelector(`#panel-${lesson.tab ?? 'plots'} [data-plot="${lesson.plot}"]`);
    for (const old of document.querySelectorAll('.lesson-plot')) if (old !== plot) old.classList.remove('lesson-plot');
    if (!lesson || !(plot instanceof HTMLElement)) return;
    plot.classList.add('lesson-plot');
    if (!this.ran) return;
    this.draw(plot);
    // Elsewhere a lesson opens at the page's top, where its panel is.
    if (document.body.classList.contains('present') && getComputedStyle(this.panel).position === 'sticky')
      keepWhole(plot);
    this.panel.dataset.shown = lesson.id;
  }

  /**
   * Opens the lesson named `id` (its link's name); returns false, opening nothing, when no lesson
   * has that name.
   * @param {string} id
   */
  openById(id) {
    const i = this.lessons.findIndex((l) => l.id === id);
    if (i < 0) return false;
    this.open(i);
    return true;
  }

  close() {
    this.index = null;
    this.showPlot();
    delete this.panel.dataset.shown;
    this.panel.hidden = true;
    document.body.classList.remove('with-lesson');
  }
}
