// Guided lessons: a list in the Lessons tab, and a lesson panel beside the plots that keeps the
// lesson's context (what to look for, the question, a hint, the answer) while its plots are shown.
import { el } from '../ui/dom.js';
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
   * lesson with settings of its own; it resolves with how that scenario differs from the lesson's
   * run ("key: lesson's → link's"), empty when it does not.
   * @param {{panel: HTMLElement, list: HTMLElement, lessons: Lesson[],
   *   onOpen: (lesson: Lesson, link: string | null) => Promise<string[]>}} parts
   */
  constructor({ panel, list, lessons, onOpen }) {
    this.panel = panel;
    this.lessons = lessons;
    this.onOpen = onOpen;
    /** @type {number | null} the lesson open, by its place in `lessons` */
    this.index = null;
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
    this.index = i;
    const lesson = this.lessons[i];
    const previous = el('button', { type: 'button', textContent: '← Previous', disabled: i === 0 });
    const next = el('button', { type: 'button', textContent: 'Next →', disabled: i === this.lessons.length - 1 });
    const close = el('button', { type: 'button', className: 'close', textContent: 'Close lesson' });
    const copy = el('button', { type: 'button', className: 'copy-lesson', textContent: 'Copy link to this lesson' });
    const copied = el('p', { className: 'hint', role: 'status' });
    const own = el('div', { className: 'own-settings warning', hidden: true });
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
    this.panel.replaceChildren(
      close,
      el('p', {
        className: 'lesson-count',
        textContent: `Lesson ${i + 1} of ${this.lessons.length} · run ${lesson.run}`,
      }),
      el('h2', { textContent: lesson.title, tabIndex: -1 }),
      own,
      el('h3', { textContent: 'What to look for' }),
      el('p', { className: 'look', textContent: lesson.look }),
      el('h3', { className: 'question-head', textContent: 'Question' }),
      el('p', { className: 'question', textContent: lesson.question }),
      hint,
      answer,
      el('div', { className: 'buttons' }, [previous, next, copy]),
      copied,
    );
    this.panel.dataset.open = lesson.run;
    this.panel.hidden = false;
    this.panel.scrollTop = 0;
    document.body.classList.add('with-lesson');
    setFragment('lesson', lesson.id);
    // Keyboard and screen-reader users continue where the content is, not at the page's top.
    const started = this.onOpen(lesson, link);
    /** @type {HTMLHeadingElement} */ (this.panel.querySelector('h2')).focus({ preventScroll: true });
    const differences = await started;
    if (differences.length && this.index === i) this.showOwn(own, differences, i);
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

  close() {
    this.index = null;
    this.panel.hidden = true;
    document.body.classList.remove('with-lesson');
    setFragment('lesson', null);
  }
}
