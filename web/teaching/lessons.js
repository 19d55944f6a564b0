// Guided lessons: a list in the Lessons tab, and a lesson panel beside the plots that keeps the
// lesson's context (what to look for, the question, a hint, the answer) while its plots are shown.
import { el } from '../ui/dom.js';

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
   * lesson's run (a scenario string).
   * @param {{panel: HTMLElement, list: HTMLElement, lessons: Lesson[],
   *   onOpen: (lesson: Lesson) => Promise<void>}} parts
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
    this.panel.replaceChildren(
      close,
      el('p', {
        className: 'lesson-count',
        textContent: `Lesson ${i + 1} of ${this.lessons.length} · run ${lesson.run}`,
      }),
      el('h2', { textContent: lesson.title, tabIndex: -1 }),
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
    // Keyboard and screen-reader users continue where the content is, not at the page's top.
    const started = this.onOpen(lesson);
    /** @type {HTMLHeadingElement} */ (this.panel.querySelector('h2')).focus({ preventScroll: true });
    await started;
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
    this.panel.hidden = true;
    document.body.classList.remove('with-lesson');
  }
}
