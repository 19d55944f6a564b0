// The protocol between the page and the worker: every message, its fields and its reply, as
// types the TypeScript compiler checks (`make test` runs `tsc` over the page and the worker).
// The module holds no code: the page's clients (client/) and the worker (worker/) import its
// types. Every number in a reply comes from the core; the worker only moves messages.
//
// Requests carry `id` (a run), `req` (a describe), `job` (a job) or `serial` (an export), and the
// reply carries the same key back. Buffers of views, overlays and CSV chunks are transferred.
export {};

// ---------------------------------------------------------------------------------------------
// What the worker sends back: the parts shared by several replies.

/**
 * The samples of one plot over a window: its times and, by column name, the recorded values
 * (an M4 envelope: every point a recorded sample at its own time). The column
 * 'lyapunov_bound' is the bound (59) evaluated by the core at the plot's times; 'd2_tilde' and
 * 'd4_tilde', the unknown terms of steps 2 and 4 evaluated from the simulated truth, come alone
 * in their plot, on the times of their own envelope (none where the core does not evaluate them);
 * so do 'law_r1'..'law_r4', the residuals of the steps' designed dynamics under a scenario's own
 * laws (v_i less the paper's v_i; none without own laws).
 * @typedef {{t: Float64Array, columns: Record<string, Float64Array>}} PlotView
 */

/**
 * The view of a set of plots over the window [t0, t1].
 * @typedef {{t0: number, t1: number, plots: Record<string, PlotView>}} View
 */

/**
 * The plots' columns, `{plotId: [column, ...]}`: each plot gets its own envelope.
 * @typedef {Record<string, string[]>} Groups
 */

/**
 * A scenario as the core describes it (the core's `describe`): its canonical text in `encoded`,
 * its fields and the keys it changes of its preset; `rejected` holds the messages of the fields a
 * `recover` dropped, each naming its field. The core's binding documents the other fields.
 * @typedef {{encoded: string, rejected?: string[], [field: string]: any}} Info
 */

/**
 * A figure of a finished run (the core's report).
 * @typedef {{name: string, label: string, value: number, unit: string, [more: string]: any}} Figure
 */

// ---------------------------------------------------------------------------------------------
// Page → worker.

/** @typedef {{type: 'describe' | 'recover', req: number, scenario: string}} DescribeRequest */
/**
 * Starts run `id` (a new run ends the last). `overlay`, a column or null, is kept as the run goes
 * for the overlay with the pins.
 * @typedef {{type: 'run', id: number, scenario: string, groups: Groups, buckets: number, overlay: string | null}} RunRequest
 */
/** @typedef {{type: 'cancel', id: number}} CancelRequest */
/**
 * A view of run `id`'s plots `groups` over [t0, t1]; `set` names the page's plot set and comes back.
 * @typedef {{type: 'view', id: number, set: string, groups: Groups, t0: number, t1: number, buckets: number}} ViewRequest
 */
/**
 * Run `id`'s CSV, sent in chunks of rows: the page asks for each next chunk ('csv-next') once it
 * has stored the last; 'csv-cancel' (or a new run) ends the export.
 * @typedef {{type: 'csv', id: number, serial: number}} CsvRequest
 * @typedef {{type: 'csv-next' | 'csv-cancel', serial: number}} CsvNextRequest
 */
/** @typedef {{type: 'inspect', id: number, t: number}} InspectRequest */
/** Run `id`'s scenario with each EKF predictor, to the end. @typedef {{type: 'compare', id: number}} CompareRequest */
/**
 * Runs each scenario in time slices and pins it, keeping the overlay's `column`; 'pin-cancel'
 * stops at the next slice.
 * @typedef {{type: 'pin', scenarios: string[], column: string}} PinRequest
 * @typedef {{type: 'pin-cancel'}} PinCancelRequest
 * @typedef {{type: 'unpin', index: number}} UnpinRequest
 * @typedef {{type: 'unpin-all'}} UnpinAllRequest
 */
/**
 * The overlay of run `id` and the pins in `column` over [t0, t1]. Every run keeps `column` from
 * then on: the next overlay of it replays none.
 * @typedef {{type: 'overlay', id: number, column: string, t0: number, t1: number, buckets: number}} OverlayRequest
 */
/**
 * Run `id`'s measures for judging a challenge.
 * @typedef {{type: 'challenge-measure', id: number}} MeasureRequest
 */
/**
 * A stateless job (any worker of a pool can take it): `kind` names it, its fields follow.
 * @typedef {{type: 'job', job: number} & JobRequest} JobMessage
 */

/**
 * Every message the page sends.
 * @typedef {DescribeRequest | RunRequest | CancelRequest | ViewRequest | CsvRequest | CsvNextRequest
 *   | InspectRequest | CompareRequest | PinRequest | PinCancelRequest | UnpinRequest | UnpinAllRequest | OverlayRequest
 *   | MeasureRequest | JobMessage} ToWorker
 */

// ---------------------------------------------------------------------------------------------
// The jobs: `kind`, the fields it needs, and its result.

/**
 * Every job, by kind: `req` its fields, `result` what it resolves with.
 * - 'sweep': one point of a frequency sweep of `scenario` with `changes` ([key, value] pairs).
 * - 'seed': `scenario` run with `seed`, its figures kept every `every` samples.
 * - 'grid', 'seed-range': the core's log-spaced frequencies and seed list.
 * - 'bands', 'summary', 'sweep-csv', 'seeds-csv': summaries and CSVs of finished points and runs.
 * - 'map-plan': the model-error map `text` over `scenario` (its cells and seeds) and the figures
 *   it keeps; 'map-run' one cell's scenario with one seed; 'map-cells' the cells of `runs`;
 *   'map-csv' the map's CSV.
 * - 'challenge': the description of the challenge a link opens (a challenge link, a submission
 *   link, a built-in's name); 'challenge-submission' a submission link read against it;
 *   'challenge-tries' the submission of a student's values ([field, value] pairs), its link
 *   written by the core; 'challenge-compose' a challenge composed from a lecturer's parts (its
 *   link and brief, or the part at fault); 'challenge-designs' at most `max` designs within its
 *   allowed ranges for a check to try (each [field, value] pairs, the base's empty one first);
 *   'challenge-judge' the verdict on the measures of its runs; 'challenge-run' one
 *   scenario run to its end and measured; 'challenge-builtins' and 'challenge-figures' the
 *   built-in challenges and the figures a criterion may name.
 * - 'law-language': the names and functions a step's own law may use; 'law-preview' the law
 *   `text` of `step` as typed (its TeX, or where and why it is refused); 'law-verdicts' the
 *   verdict on each own law of `scenario` against its step's designed dynamics.
 * - 'grade-class': a class's file read against a challenge (a built-in's name or a link): the
 *   CSV's header and the submissions; 'grade-link' one submission graded, its runs run and its
 *   CSV row written. The CSV is the header and then each row's `csv`, in file order.
 * @typedef {{
 *   sweep: {req: {scenario: string, changes: [string, string][], freq: number, amp: number, duration: number, offset: number}, result: any},
 *   seed: {req: {scenario: string, seed: number, every: number}, result: any},
 *   grid: {req: {lo: number, hi: number, n: number}, result: number[]},
 *   'seed-range': {req: {first: number, n: number}, result: number[]},
 *   bands: {req: {runs: any[]}, result: any},
 *   summary: {req: {points: any[]}, result: any},
 *   'sweep-csv': {req: {points: any[]}, result: string},
 *   'seeds-csv': {req: {results: any[]}, result: string},
 *   'map-plan': {req: {scenario: string, text: string}, result: {map: any, figures: any[]}},
 *   'map-run': {req: {scenario: string, seed: number}, result: any},
 *   'map-cells': {req: {map: any, runs: any[]}, result: any[]},
 *   'map-csv': {req: {map: any, cells: any[]}, result: string},
 *   challenge: {req: {text: string}, result: any},
 *   'challenge-submission': {req: {text: string, submission: string}, result: any},
 *   'challenge-tries': {req: {text: string, tries: [string, string][]}, result: any},
 *   'challenge-compose': {req: {parts: any}, result: {encoded: string | null, brief: string | null, error: {key: string, message: string} | null}},
 *   'challenge-designs': {req: {text: string, max: number}, result: [string, string][][]},
 *   'challenge-judge': {req: {text: string, runs: any[]}, result: any},
 *   'challenge-run': {req: {scenario: string}, result: any},
 *   'challenge-builtins': {req: {}, result: {name: string, summary: string, text: string, solution: string}[]},
 *   'challenge-figures': {req: {}, result: {name: string, label: string, unit: string}[]},
 *   'law-language': {req: {}, result: {names: any[], functions: {name: string, doc: string}[]}},
 *   'law-preview': {req: {step: number, text: string}, result: {tex: string | null, error: {at: number, len: number, reason: string} | null, designed: string}},
 *   'law-verdicts': {req: {scenario: string}, result: {step: number, designed: boolean, worst: number, finding: string | null, text: string}[]},
 *   'grade-class': {req: {text: string, bytes: Uint8Array}, result: ClassFile},
 *   'grade-link': {req: {text: string, row: ClassRow}, result: Graded},
 * }} Jobs
 */

/**
 * A submission of a class's file: its line, its link, the cells carried from a CSV export, and a
 * status when it was graded as it was read (a line that is not text).
 * @typedef {{line: number, link: string, carried: string[], status: string | null}} ClassRow
 */
/**
 * A class's file read: the CSV header line (with its line end), the carried columns, the column
 * of links, the submissions; `error` when the challenge or the file is refused whole.
 * @typedef {{header: string, columns: string[], link_column: string | null, rows: ClassRow[],
 *   error: string | null}} ClassFile
 */
/**
 * A graded submission: its status ("ok", or why it was not judged), whether it passed, the
 * core's verdict, and its CSV row (with its line end).
 * @typedef {{line: number, link: string, status: string, pass: boolean, verdict: any, csv: string}} Graded
 */

/**
 * A job's request: its kind and fields.
 * @typedef {{[K in keyof Jobs]: {kind: K} & Jobs[K]['req']}[keyof Jobs]} JobRequest
 */

// ---------------------------------------------------------------------------------------------
// Worker → page.

/**
 * Unprompted, once the core is loaded: the presets and the NIS band of the EKF's consistency.
 * @typedef {{type: 'ready', presets: any[], nisBand: any}} Ready
 */
/**
 * Unprompted: the core trapped (a panic, running out of memory) or the worker hit an uncaught
 * error. The worker never calls the core again; the page replaces it.
 * @typedef {{type: 'crashed', message: string}} Crashed
 */
/** @typedef {{type: 'described', req: number, info: Info}} Described */
/**
 * A request the core refused: `req` for a describe, `id` for a run's request.
 * @typedef {{type: 'invalid', req?: number, id?: number, message: string}} Invalid
 */
/** @typedef {{type: 'progress', id: number, done: number, total: number}} Progress */
/**
 * Run `id` ended: `view` is the whole run's view of its `groups` (null when it recorded nothing),
 * `failure` why it stopped early, and the core's report (figures, warnings, …).
 * @typedef {{type: 'done', id: number, rows: number, failure: string | null, view: View | null,
 *   computeMs: number, stability: any, figures: Figure[], unreached: any[], transient: any,
 *   warnings: any[]}} Done
 */
/** @typedef {{type: 'cancelled', id: number}} Cancelled */
/** @typedef {{type: 'view', id: number, set: string, view: View}} ViewReply */
/**
 * One chunk of a CSV export (the chunks concatenate to the CSV; the last has rows === total).
 * @typedef {{type: 'csv', serial: number, bytes: Uint8Array, rows: number, total: number}} CsvChunk
 * @typedef {{type: 'csv-failed', serial: number, message: string}} CsvFailed
 */
/** @typedef {{type: 'inspected', id: number, t: number, snapshot: any}} Inspected */
/**
 * @typedef {{type: 'compared', id: number, results: {predictor: string, scenario: string, metrics: any}[]}} Compared
 */
/**
 * @typedef {{type: 'pin-progress', index: number, count: number, done: number, total: number}} PinProgress
 * @typedef {{type: 'pins', scenarios: string[], legends: string[], rejected: {scenario: string, message: string}[]}} Pins
 */
/**
 * The overlay's samples: times, the current run, each pin, then each pin's difference to the run.
 * @typedef {{type: 'overlay', id: number, column: string, data: Float64Array[]}} OverlayReply
 */
/**
 * `measures` is null when the worker no longer holds run `id`.
 * @typedef {{type: 'challenge-measured', id: number, measures: any, error?: string}} Measured
 */
/** @typedef {{type: 'job', job: number, result?: any, error?: string}} JobReply */

/**
 * Every message the worker sends.
 * @typedef {Ready | Crashed | Described | Invalid | Progress | Done | Cancelled | ViewReply | CsvChunk
 *   | CsvFailed | Inspected | Compared | PinProgress | Pins | OverlayReply | Measured | JobReply} FromWorker
 */

/**
 * The page's handlers of the messages no request waits on, by type.
 * @typedef {{[T in FromWorker['type']]?: (data: Extract<FromWorker, {type: T}>) => void}} Handlers
 */
