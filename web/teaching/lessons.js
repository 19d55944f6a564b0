// Guided lessons: a list in the Lessons tab, and a lesson panel beside the plots that keeps the
// lesson's context (what to look for, the question, a hint, the answer) while its plots are shown.
import { el } from '../ui/dom.js';
import { keepWhole } from './layout.js';
import { fragment, setFragment } from '../ui/url.js';
import { withLanguage } from '../ui/language.js';
import { language, loadRest, t } from '../l10n/l10n.js';
import { LESSON_TEXTS, measuredArgs } from './measured.js';
import { loadTable, theTable } from './table.js';

/** @typedef {import('./teaching.js').Lesson} Lesson */

/**
 * The link to `lesson`: its run, and its name, which opens its panel; in presentation mode, that
 * mode too; and the language shown.
 * @param {Lesson} lesson
 */
export const lessonLink = (lesson) =>
  withLanguage(
    `${location.origin}${location.pathname}?${lesson.run}#lesson=${lesson.id}${fragment('present') === '1' ? '&present=1' : ''}`,
  );

/** @type {Record<string, string | number> | null} the measurements, shown in the language shown */
let measured = null;

/**
 * The texts of `lesson` a student reads, in the language shown, with their measured numbers.
 * The teaching messages must be loaded.
 * @param {Lesson} lesson
 * @returns {Record<(typeof LESSON_TEXTS)[number], string>}
 */
export function lessonText(lesson) {
  measured ??= measuredArgs(theTable(), language);
  const args = measured;
  return /** @type {Record<(typeof LESSON_TEXTS)[number], string>} */ (
    Object.fromEntries(LESSON_TEXTS.map((k) => [k, t(`${lesson.id}-${k}`, args)]))
  );
}

/**
 * Copies the link to `lesson`, saying so in `said` (or showing the link where the clipboard is refused).
 * @param {Lesson} lesson
 * @param {HTMLElement} said
 */
async function copyLink(lesson, said) {
  const link = lessonLink(lesson);
  try {
    await navigator.clipboard.writeText(link);
    said.textContent = t('lesson-link-copied');
  } catch {
    said.textContent = t('lesson-copy-this-link', { link });
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
    this.list = list;
    /** @type {Promise<void> | null} the lessons' texts, loaded, and their list filled */
    this.loaded = null;
  }

  /** Loads the lessons' texts (once) and lists the lessons; resolves when they are listed. */
  texts() {
    this.loaded ??= Promise.all([loadRest(), loadTable()]).then(
      () => {
        this.lessons.forEach((lesson, i) => {
          const text = lessonText(lesson);
          const start = el('button', { type: 'button', textContent: t('lesson-start', { number: i + 1 }) });
          start.dataset.lesson = lesson.run;
          start.addEventListener('click', () => this.open(i));
          this.list.append(
            el('article', { className: 'lesson' }, [
              el('h3', { textContent: t('lesson-numbered-title', { number: i + 1, title: text.title }) }),
              el('p', { textContent: text.look }),
              el('p', { className: 'question', textContent: t('lesson-list-question', { question: text.question }) }),
              start,
            ]),
          );
        });
      },
      (e) => {
        this.loaded = null;
        throw e;
      },
    );
    return this.loaded;
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
    const lesson = this.lessons[i];
    const loaded = this.onOpen(lesson, link);
    await this.texts();
    if (me !== this.opened) return;
    this.show(i);
    // Keyboard and screen-reader users continue where the content is, not at the page's top.
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
    const text = lessonText(lesson);
    const previous = el('button', {
      type: 'button',
      className: 'previous',
      textContent: t('lesson-previous'),
      disabled: i === 0,
    });
    const next = el('button', {
      type: 'button',
      className: 'next',
      textContent: t('lesson-next'),
      disabled: i === this.lessons.length - 1,
    });
    const close = el('button', { type: 'button', className: 'close', textContent: t('lesson-close') });
    // Presentation mode shows the label's first words only (style), and reads it whole.
    const copy = el('button', { type: 'button', className: 'copy-lesson' }, [
      t('lesson-copy-link-short'),
      el('span', { className: 'rest', textContent: t('lesson-copy-link-rest') }),
    ]);
    const copied = el('p', { className: 'hint', role: 'status' });
    copy.addEventListener('click', () => copyLink(lesson, copied));
    previous.addEventListener('click', () => this.open(i - 1));
    next.addEventListener('click', () => this.open(i + 1));
    close.addEventListener('click', () => this.close());
    const hint = el('details', { className: 'hint' }, [
      el('summary', { textContent: t('lesson-hint') }),
      el('p', { textContent: text.hint }),
    ]);
    const answer = el('details', { className: 'answer' }, [
      el('summary', { textContent: t('lesson-show-answer') }),
      el('p', { textContent: text.answer }),
    ]);
    // The parts in reading order; presentation mode (style) puts the question under the title
    // and lets what to look for, the hint and the answer scroll in their own boxes below it.
    this.panel.replaceChildren(
      close,
      el('p', { className: 'lesson-count' }, [
        t('lesson-count', { number: i + 1, count: this.lessons.length }),
        el('span', { className: 'lesson-run', textContent: t('lesson-run', { run: lesson.run }) }),
      ]),
      el('h2', { textContent: text.title, tabIndex: -1 }),
      el('div', { className: 'own-settings warning', hidden: true }),
      el('div', { className: 'lesson-look' }, [
        el('h3', { textContent: t('lesson-look-head') }),
        el('p', { className: 'look', textContent: text.look }),
      ]),
      el('div', { className: 'lesson-question' }, [
        el('h3', { className: 'question-head', textContent: t('lesson-question-head') }),
        el('p', { className: 'question', textContent: text.question }),
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
  async follow(id) {
    const i = id === null ? -1 : this.lessons.findIndex((l) => l.id === id);
    const me = ++this.opened;
    if (i < 0) {
      if (this.index !== null) this.close(false);
      return;
    }
    await this.texts();
    if (me !== this.opened) return;
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
    const back = el('button', { type: 'button', textContent: t('lesson-load-run') });
    back.addEventListener('click', () => this.open(i));
    own.replaceChildren(
      el('p', {
        textContent: t('lesson-own-settings', { differences: differences.join('; ') }),
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
