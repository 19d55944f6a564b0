// The page's measurements table, parsed once from the bundled tables: every text the page
// renders (lessons, walkthrough) reads its numbers here.
import { TABLES } from './measurements.js';
import { parseTables } from './measured.js';

export const TABLE = parseTables(TABLES);
