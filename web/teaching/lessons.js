// Guided lessons: a list in the Lessons tab, and a lesson panel beside the plots that keeps the
// lesson's context (what to look for, the question, a hint, the answer) while its plots are shown.
import { el } from '../ui/dom.js';
import { keepWhole } from './layout.js';
import { fragment, setFragment } from '../ui/url.js';

/** @typedef {import('./teaching.js').Lesson} Lesson */

/**
 * The link to `lesson`: its run, and its name, which opens its panel; in presentation mode, that
 * mode too.
 * @param {Lesson} lesson
 */
export const lessonLink = (lesson) =>
  `${location.origin}${location.pathname}?${lesson.run}#lesson=${lesson.id}${fragment('present') === '1' ? '&present=1' : ''}`;

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
   * `panel` receives the open lesson, `list` the lesson cards. `onOpen(lesson, link)` loads and
   * runs the lesson's run (a scenario string), or the scenario `link` of an address that names the
   * lesson with settings of its own; `differences(lesson, link)` finds how such a scenario
   * differs from the lesson's run ("key: lesson's → link's", empty when it does not). `draw(plot)`
   * draws a plot's chart that waits to come into view.
   * @param {{panel: HTMLElement, list: HTMLElement, lessons: Lesson[],
   *   onOpen: (lesson: Lesson, link: string | null) => Promise<void>,
   *   differences: (lesson: Lesson, link: string) => Promise<string[]>,
   *   draw: (plot: HTMLElement) => void}} parts
   */
  constructor({ panel, list, lessons, onOpen, differences, draw }) {
    this.panel = panel;
    this.lessons = lessons;
    this.onOpen = onOpen;
    this.differences = differences;
    this.draw = draw;
    /** @type {number | null} the lesson open, by its place in `lessons` */
    this.index = null;
    this.ran = false; // whether the open lesson's run has been drawn
    this.mapShown = false; // whether the open lesson's map has been drawn
    this.opened = 0; // the lessons opened, and the address followed: a later one ends an earlier's
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
   * Opens lesson `i`: shows its panel, scrolled to the top, with focus on its title, and runs it,
   * or the scenario `link` when an address names the lesson with settings of its own. The address
   * names the lesson while it is open, so that a reload opens it again.
   * @param {number} i
   * @param {string | null} [link]
   */
  async open(i, link = null) {
    const me = ++this.opened;
    this.show(i);
    const lesson = this.lessons[i];
    // Keyboard and screen-reader users continue where the content is, not at the page's top.
    const loaded = this.onOpen(lesson, link);
    /** @type {HTMLHeadingElement} */ (this.panel.querySelector('h2')).focus({ preventScroll: true });
    this.showPlot();
    await loaded;
    if (me !== this.opened) return;
    // Named once its run is the address's: an entry before it keeps what it was.
    setFragment('lesson', lesson.id);
    await this.compare(i, link, me);
  }

  /**
   * Says, when scenario `link` is not lesson `i`'s run, how it differs from it (unless another
   * lesson was opened, or the address followed, since opening `me`); else says nothing.
   * @param {number} i
   * @param {string | null} link
   * @param {number} me
   */
  async compare(i, link, me) {
    const own = /** @type {HTMLElement} */ (this.panel.querySelector('.own-settings'));
    own.hidden = true;
    const lesson = this.lessons[i];
    if (link === null || link === lesson.run) return;
    const found = await this.differences(lesson, link);
    if (found.length && me === this.opened) this.showOwn(own, found, i);
  }

  /**
   * Shows lesson `i`'s panel, scrolled to the top, without running anything.
   * @param {number} i
   */
  show(i) {
    this.index = i;
    const lesson = this.lessons[i];
    const previous = el('button', { type: 'button', textContent: '← Previous', disabled: i === 0 });
    const next = el('button', { type: 'button', textContent: 'Next →', disabled: i === this.lessons.length - 1 });
    const close = el('button', { type: 'button', className: 'close', textContent: 'Close lesson' });
    // Presentation mode shows the label's first words only (style), and reads it whole.
    const copy = el('button', { type: 'button', className: 'copy-lesson' }, [
      'Copy link',
      el('span', { className: 'rest', textContent: ' to this lesson' }),
    ]);
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
      el('div', { className: 'own-settings warning', hidden: true }),
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
    this.mapShown = false;
    this.panel.hidden = false;
    this.panel.scrollTop = 0;
    document.body.classList.add('with-lesson');
  }

  /**
   * Follows the address after Back or Forward: shows the panel of the lesson it names (`id`), or
   * none; the address's scenario is loaded by the caller.
   * @param {string | null} id
   */
  follow(id) {
    const i = id === null ? -1 : this.lessons.findIndex((l) => l.id === id);
    const me = ++this.opened;
    if (i < 0) {
      if (this.index !== null) this.close(false);
      return;
    }
    if (i !== this.index) this.show(i);
    this.compare(i, location.search.slice(1) || null, me);
  }

  /**
   * Says, in `own`, that the address's settings are shown in place of lesson `i`'s run, and how
   * they differ from it (`differences`), with a button that loads the lesson's run.
   * @param {HTMLElement} own
   * @param {string[]} differences
   * @param {number} i
   */
  showOwn(own, differences, i) {
    const back = el('button', { type: 'button', textContent: 'Load the lesson’s run' });
    back.addEventListener('click', () => this.open(i));
    own.replaceChildren(
      el('p', {
        textContent: `This link holds settings of its own, and they are shown as it has them, not the lesson’s run: ${differences.join('; ')}. What the lesson says of its run need not hold for them.`,
      }),
      back,
    );
    own.hidden = false;
  }

  /** The open lesson's run has been drawn: its plot is shown. */
  afterRun() {
    if (this.index === null || this.ran) return;
    this.ran = true;
    this.showPlot(true);
  }

  /** The map has been drawn: a lesson about it shows it, brought into view the first time. */
  mapDrawn() {
    if (this.index === null || this.lessons[this.index].plot !== 'map') return;
    this.showPlot(!this.mapShown);
    this.mapShown = true;
  }

  /**
   * Marks the plot the open lesson's question is about (`lesson-plot`: presentation mode puts it
   * first among the Trajectories plots) and, once the lesson's run is drawn, in presentation mode
   * with the lesson beside the results, brings it whole into view; the panel's `data-shown` then
   * names the lesson. Called again when a plot is drawn anew (the lesson's map); `scroll` brings
   * it into view.
   */
  showPlot(scroll = false) {
    const lesson = this.index === null ? null : this.lessons[this.index];
    const plot = lesson && document.querySelector(`#panel-${lesson.tab ?? 'plots'} [data-plot="${lesson.plot}"]`);
    for (const old of document.querySelectorAll('.lesson-plot')) if (old !== plot) old.classList.remove('lesson-plot');
    if (!lesson || !(plot instanceof HTMLElement)) return;
    plot.classList.add('lesson-plot');
    if (!this.ran) return;
    this.draw(plot);
    // Elsewhere a lesson opens at the page's top, where its panel is.
    if (scroll && document.body.classList.contains('present') && getComputedStyle(this.panel).position === 'sticky')
      keepWhole(plot);
    this.panel.dataset.shown = lesson.id;
  }

  /**
   * Opens the lesson named `id` (its link's name) with the address's scenario `link` (null when the
   * address holds none); returns false, opening nothing, when no lesson has that name.
   * @param {string} id
   * @param {string | null} link
   */
  openById(id, link) {
    const i = this.lessons.findIndex((l) => l.id === id);
    if (i < 0) return false;
    this.open(i, link);
    return true;
  }

  /** Closes the lesson; with `address`, the address no longer names it. */
  close(address = true) {
    this.index = null;
    this.showPlot();
    delete this.panel.dataset.shown;
    this.panel.hidden = true;
    document.body.classList.remove('with-lesson');
    if (address) setFragment('lesson', null);
  }
}
