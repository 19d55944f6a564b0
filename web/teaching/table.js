// The page's measurements table, parsed once from the bundled tables: every text the page
// renders (lessons, walkthrough) reads its numbers here. The tables come in their own chunk,
// fetched with the rest of the messages (the texts that read them come with those): the first
// plot does not wait for them.
import { parseTables } from './measured.js';

/** @type {ReturnType<typeof parseTables> | null} */
let table = null;
/** @type {Promise<void> | null} */
let loading = null;

/** Fetches and parses the tables, once; a failed fetch is tried again on the next call. */
export function loadTable() {
  loading ??= import('./measurements.js').then(
    ({ TABLES }) => {
      table = parseTables(TABLES);
    },
    (e) => {
      loading = null;
      throw e;
    },
  );
  return loading;
}

/** Whether the tables are loaded. */
export const tableLoaded = () => table !== null;

/** The parsed tables; loaded first (see loadTable). */
export function theTable() {
  if (table === null) throw new Error('the measurements table is read before it is loaded');
  return table;
}
