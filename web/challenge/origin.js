// Where an open challenge comes from, as the challenge header says it: a built-in, one that this
// browser's composer made, or any other (a copy with an edited bound or title among them). This
// browser keeps the SHA-256 digest of the canonical text of every challenge its composer makes,
// in its own storage: a link carries nothing of it, so no link can claim it, and another
// browser (or this one, once its site data is cleared) knows none of them. The canonical text is
// the core's (its challenge link without a student's try.* parts); nothing here reads a link.
import { el } from '../ui/dom.js';
import { t } from '../l10n/l10n.js';

/** @import { RunClient } from '../client/run-client.js' */
/** @import { Challenge } from './challenge.js' */

/**
 * Where a challenge comes from: a built-in, composed in this browser, not composed in this browser
 * (as far as its record goes), or unknown (this browser keeps no record).
 * @typedef {'builtin' | 'mine' | 'other' | 'unknown'} Origin
 */

/** The storage key of the digests, oldest first. */
const STORE = 'imlab.composed-challenges';
/** The most digests kept (64 characters each): the oldest are dropped beyond it. */
const KEEP = 2000;

/** What the header says of each origin, by its message: text, so that it never rests on colour. */
const SAY = {
  builtin: 'challenge-origin-builtin',
  mine: 'challenge-origin-mine',
  other: 'challenge-origin-other',
  unknown: 'challenge-origin-unknown',
};

/**
 * The digests this browser keeps, or null where it can keep none (no Web Crypto outside a secure
 * context, storage blocked or unavailable).
 * @returns {string[] | null}
 */
function kept() {
  try {
    if (!globalThis.crypto?.subtle) return null;
    const list = JSON.parse(localStorage.getItem(STORE) ?? '[]');
    return Array.isArray(list) ? list.filter((d) => typeof d === 'string') : [];
  } catch {
    return null;
  }
}

/** The SHA-256 digest of `text`, in hex. @param {string} text */
async function digest(text) {
  const bytes = new Uint8Array(await crypto.subtle.digest('SHA-256', new TextEncoder().encode(text)));
  return Array.from(bytes, (b) => b.toString(16).padStart(2, '0')).join('');
}

/**
 * Records that this browser composed the challenge of canonical text `text`; resolves to whether
 * its storage took the record (never rejects).
 * @param {string} text
 */
export async function remember(text) {
  if (!kept()) return false;
  try {
    const d = await digest(text);
    // Read after the digest, so that another make meanwhile (another tab) is kept too.
    const list = kept() ?? [];
    const rest = list.filter((x) => x !== d);
    localStorage.setItem(STORE, JSON.stringify([...rest.slice(-(KEEP - 1)), d]));
    return true;
  } catch {
    return false;
  }
}

/**
 * Where the challenge of canonical text `text` comes from; `client` lists the built-ins (never
 * rejects: what cannot be told is 'unknown').
 * @param {RunClient} client
 * @param {string} text
 * @returns {Promise<Origin>}
 */
export async function originOf(client, text) {
  try {
    const builtins = await client.job('challenge-builtins');
    if (builtins.some((b) => b.text === text)) return 'builtin';
    const list = kept();
    if (!list) return 'unknown';
    return list.includes(await digest(text)) ? 'mine' : 'other';
  } catch {
    return 'unknown';
  }
}

/** Says that a link claims built-in challenge `name` with other terms. @param {string} name */
const editedNote = (name) =>
  el('p', {
    id: 'challenge-edited',
    className: 'warning',
    textContent: t('challenge-edited', { name }),
  });

/**
 * The challenge header for `desc` from `origin`: its title, its fingerprint, where it comes from
 * (which a screen reader reads with the title: it describes the heading), and the edited note.
 * @param {Challenge} desc
 * @param {Origin} origin
 */
export function header(desc, origin) {
  const title = el('h2', { textContent: desc.title, tabIndex: -1 });
  title.setAttribute('aria-describedby', 'challenge-origin');
  const mark = el('p', { id: 'challenge-origin', className: `origin origin-${origin}`, textContent: t(SAY[origin]) });
  mark.setAttribute('role', 'note');
  mark.dataset.origin = origin;
  return [
    el('p', { className: 'lesson-count', textContent: t('challenge-kind') }),
    title,
    mark,
    // What a lecturer compares at a glance with `imlab challenge`'s: the challenge's terms.
    el('p', { className: 'fingerprint hint' }, [
      t('challenge-fingerprint'),
      ' ',
      el('code', { id: 'challenge-fingerprint', textContent: desc.fingerprint }),
    ]),
    ...(desc.edited_from ? [editedNote(desc.edited_from)] : []),
  ];
}
