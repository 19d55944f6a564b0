// The protocol between the page and the worker: every message, its fields and its reply, as
// types the TypeScript compiler checks (`make test` runs `tsc` over the page and the worker).
// The module holds no code: the page's clients (client/) and the worker (worker/) import its
// types. Every number in a reply comes from the core; the worker only moves messages.
//
// What the core says to a person crosses as its message (an id and arguments): the worker sends
// it as the core gives it, and the page's client says it in the language shown before any part of
// the page reads the reply (l10n.js, spoken). The replies are typed as the worker sends them
// (FromWorker, RawJobs); the page reads them said (ToPage, Jobs, and the types it names: Info,
// RunFigure, Checked).
//
// Requests carry `id` (a run), `req` (a describe), `job` (a job) or `serial` (an export), and the
// reply carries the same key back. Buffers of views, overlays and CSV chunks are transferred.
export {};

/**
 * The core's own types, declared in its bindings' `.d.ts` from the Rust structures (tsify): what
 * a reply carries is what the core wrote.
 * @import {Cell, ChallengeParts, ChallengeVerdict, ChallengeView, ClassRow, ClassView,
 *   Composed, CriterionFigure, Description, Entry, Figure, FigureInfo, GradedView, Identified, Language, LawVerdict, Line, Measures,
 *   MapParts, Metrics, PlanView, PresetInfo, Preview, Report, RobustMap, MapRun, SeedBands, SeedResult, SeedRun,
 *   Snapshot, Stability, SubmissionView, SweepPoint, SweepSummary, BuiltinView, Message} from '../../pkg/imlab.js'
 */

/**
 * A value of the core as the page reads it, its messages said (see core-message.js).
 * @template T
 * @typedef {import('../l10n/core-message.js').Spoken<T>} Spoken
 */

// ---------------------------------------------------------------------------------------------
// What the worker sends back: the parts shared by several replies.

/**
 * The samples of one plot over a window: its times and, by column name, the recorded values
 * (an M4 envelope: every point a recorded sample at its own time). The column
 * 'lyapunov_bound' is the bound (59) evaluated by the core at the plot's times; 'd2_tilde' and
 * 'd4_tilde', the unknown terms of steps 2 and 4 evaluated from the simulated truth, come alone
 * in their plot, on the times of their own envelope (none where the core does not evaluate them);
 * so do 'law_r1'..'law_r4', the residuals of the steps' designed dynamics under a scenario's own
 * laws (v_i less the paper's, or less the one that gives the designed dynamics after the
 * student's own earlier step; none without own laws); and so do 'zdot1'..'zdot4' and
 * 'zdes1'..'zdes4', each step's ż_i as the run made it and the designed rate (none for IFOC).
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
 * A scenario as the core describes it: its canonical text in `encoded`, its preset, its fields
 * and the keys it changes of its preset.
 * @typedef {Spoken<Description>} Info
 */
/**
 * A figure of a finished run, as the core's report writes it.
 * @typedef {Spoken<Figure>} RunFigure
 */
/** @typedef {ClassRow} ClassFileRow */
/**
 * A scenario checked: its description, or null when refused, and the fields refused.
 * @typedef {Spoken<import('../../pkg/imlab.js').Checked>} Checked
 */

// ---------------------------------------------------------------------------------------------
// Page → worker.

/**
 * A scenario checked by the core: 'describe' refuses it at its first fault, 'recover' keeps its
 * acceptable fields and lists the others; 'describe-form' checks a form's scenario, its preset and
 * each field's value as its control holds it, which the core writes into a scenario.
 * @typedef {{type: 'describe' | 'recover', req: number, scenario: string}
 *   | {type: 'describe-form', req: number, form: FormScenario}} DescribeRequest
 */
/**
 * A form's scenario: its preset, and each field's key and value as its control holds it.
 * @typedef {{preset: string, fields: [string, string][]}} FormScenario
 */
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
 * Every job, by kind: `req` its fields, `result` what it resolves with, as the worker computes it
 * (the page reads Jobs, the same said).
 * - 'sweep-plan': a sweep's plan read from its text (a link's `#sweep=`, as `imlab sweep --plan`
 *   takes it); 'sweep-plan-of' from a form's parts as written (`numbers` lo, hi, n, amp, offset,
 *   duration; `variants` their names): the plan, its text, frequencies, labels and caveats.
 * - 'sweep': one point of a frequency sweep of `variant` (a name in a plan) of `scenario`.
 * - 'seed': `scenario` run with `seed`, its figures kept every `every` samples.
 * - 'seed-range': the core's seed list.
 * - 'bands', 'summary', 'sweep-csv', 'seeds-csv': summaries and CSVs of finished points and runs.
 * - 'map-parts': a map's text in its parts (axes, seeds), for the form; 'map-plan': the
 *   model-error map of `axes` and `seeds` over `scenario` (its cells and seeds) and the figures
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
 *   built-in challenges and the figures a criterion may name, each with the bounds it may take.
 * - 'law-language': the names and functions a step's own law may use; 'law-preview' the law
 *   `text` of `step` as typed (its TeX, or where and why it is refused); 'law-verdicts' the
 *   verdict on each own law of `scenario` against its step's designed dynamics.
 * - 'design': the design `design=derived` gives the motor of `scenario`, each value with the rule
 *   behind it (as `imlab design` prints them).
 * - 'motor': the circuit a motor's nameplate and lab tests give, each value with how it was found,
 *   and the link that runs it (as `imlab motor` prints them); 'motor-example' the entry of the
 *   2.2 kW machine the method is checked on.
 * - 'scenario-differences': how scenario `text` differs from scenario `from`, a line a field
 *   ("key: from's → text's unit").
 * - 'grade-class': a class's file read against a challenge (a built-in's name or a link): the
 *   CSV's header and the submissions; 'grade-link' one submission graded, its runs run and its
 *   CSV row written. The CSV is the header and then each row's `csv`, in file order.
 * @typedef {{
 *   'sweep-plan': {req: {text: string}, result: PlanView},
 *   'sweep-plan-of': {req: {numbers: string[], variants: string[]}, result: PlanView},
 *   sweep: {req: {scenario: string, variant: string, freq: number, amp: number, duration: number, offset: number}, result: SweepPoint},
 *   seed: {req: {scenario: string, seed: number, every: number}, result: SeedRun},
 *   'seed-range': {req: {first: number, n: number}, result: number[]},
 *   bands: {req: {runs: SeedRun[]}, result: SeedBands},
 *   summary: {req: {points: SweepPoint[]}, result: SweepSummary},
 *   'sweep-csv': {req: {points: SweepPoint[]}, result: string},
 *   'seeds-csv': {req: {results: SeedResult[]}, result: string},
 *   'map-parts': {req: {text: string}, result: MapParts},
 *   'map-plan': {req: {scenario: string, axes: string[], seeds: string | null}, result: {map: RobustMap, figures: FigureInfo[]}},
 *   'map-run': {req: {scenario: string, seed: number}, result: MapRun},
 *   'map-cells': {req: {map: RobustMap, runs: MapRun[]}, result: Cell[]},
 *   'map-csv': {req: {map: RobustMap, cells: Cell[]}, result: string},
 *   challenge: {req: {text: string}, result: ChallengeView},
 *   'challenge-submission': {req: {text: string, submission: string}, result: SubmissionView},
 *   'challenge-tries': {req: {text: string, tries: [string, string][]}, result: SubmissionView},
 *   'challenge-compose': {req: {parts: ChallengeParts}, result: Composed},
 *   'challenge-designs': {req: {text: string, max: number}, result: [string, string][][]},
 *   'challenge-judge': {req: {text: string, runs: Measures[]}, result: ChallengeVerdict},
 *   'challenge-run': {req: {scenario: string}, result: Measures},
 *   'challenge-builtins': {req: {}, result: BuiltinView[]},
 *   'challenge-figures': {req: {}, result: CriterionFigure[]},
 *   'law-language': {req: {}, result: Language},
 *   'law-preview': {req: {step: number, text: string}, result: Preview},
 *   'law-verdicts': {req: {scenario: string}, result: LawVerdict[]},
 *   design: {req: {scenario: string}, result: Line[]},
 *   motor: {req: {entry: Entry}, result: Identified},
 *   'motor-example': {req: {}, result: Entry},
 *   'scenario-differences': {req: {from: string, text: string}, result: string[]},
 *   'grade-class': {req: {text: string, bytes: Uint8Array}, result: ClassView},
 *   'grade-link': {req: {text: string, row: ClassRow}, result: GradedView},
 * }} RawJobs
 */

/**
 * Every job, by kind, as the page reads its result: its messages said.
 * @typedef {{[K in keyof RawJobs]: {req: RawJobs[K]['req'], result: Spoken<RawJobs[K]['result']>}}} Jobs
 */

/**
 * A job's request: its kind and fields.
 * @typedef {{[K in keyof RawJobs]: {kind: K} & RawJobs[K]['req']}[keyof RawJobs]} JobRequest
 */

// ---------------------------------------------------------------------------------------------
// Worker → page.

/**
 * Unprompted, once the core is loaded: the presets and the NIS band of the EKF's consistency.
 * @typedef {{type: 'ready', presets: PresetInfo[], nisBand: Float64Array}} Ready
 */
/**
 * Unprompted: the core trapped (a panic, running out of memory) or the worker hit an uncaught
 * error. The worker never calls the core again; the page replaces it. `message` is the error, `panic`
 * the core's panic message if it left one, `memory` whether the trap most likely means the core ran
 * out of memory (an allocation failure aborts without a panic); the page says them in words.
 * @typedef {{type: 'crashed', message: string, panic?: string, memory?: boolean}} Crashed
 */
/** @typedef {{type: 'described', req: number, checked: import('../../pkg/imlab.js').Checked}} Described */
/**
 * A request the core refused: `req` for a describe that failed other than by its scenario's
 * fault, `id` for a run's request; `comparison` when it was the comparison of the EKF's predictors.
 * @typedef {{type: 'invalid', req?: number, id?: number, message: string, comparison?: boolean}} Invalid
 */
/** @typedef {{type: 'progress', id: number, done: number, total: number}} Progress */
/**
 * Run `id` ended: `view` is the whole run's view of its `groups` (null when it recorded nothing),
 * `failure` why it stopped early, and the core's report (figures, warnings, the peak and RMS
 * currents as multiples of the rated current, whether the mean NIS is inside its band, …).
 * @typedef {{type: 'done', id: number, rows: number, failure: string | null, view: View | null,
 *   computeMs: number, stability: Stability | null, figures: Figure[],
 *   unreached: Report['unreached'], transient: Report['transient'] | null,
 *   warnings: Report['warnings'], peak_to_rated: number | null, rms_to_rated: number | null,
 *   nis_inside: boolean | null}} Done
 */
/** @typedef {{type: 'cancelled', id: number}} Cancelled */
/** @typedef {{type: 'view', id: number, set: string, view: View}} ViewReply */
/**
 * One chunk of a CSV export (the chunks concatenate to the CSV; the last has rows === total), or
 * why the export failed: the core's message, or null when the worker no longer holds the run.
 * @typedef {{type: 'csv', serial: number, bytes: Uint8Array, rows: number, total: number}} CsvChunk
 * @typedef {{type: 'csv-failed', serial: number, message: string | null}} CsvFailed
 */
/** @typedef {{type: 'inspected', id: number, t: number, snapshot: Snapshot}} Inspected */
/**
 * @typedef {{type: 'compared', id: number, results: {predictor: string, scenario: string, metrics: Metrics | null}[]}} Compared
 */
/**
 * The pins, each with its legend (what differs from the current run, or the core's message that
 * nothing does), and each scenario not pinned: the core's message why, or, when pinning was
 * cancelled, whether it was cancelled before the scenario ran ('unrun') or while it ran.
 * @typedef {{type: 'pin-progress', index: number, count: number, done: number, total: number}} PinProgress
 * @typedef {{scenario: string, message: string} | {scenario: string, cancelled: 'unrun' | 'running'}} PinRejected
 * @typedef {{type: 'pins', scenarios: string[], legends: (Message | string)[], rejected: PinRejected[], cancelled: boolean}} Pins
 */
/**
 * The overlay's samples: times, the current run, each pin, then each pin's difference to the run.
 * @typedef {{type: 'overlay', id: number, column: string, data: Float64Array[]}} OverlayReply
 */
/**
 * `measures` is null when the worker no longer holds run `id`.
 * @typedef {{type: 'challenge-measured', id: number, measures: Measures | null, error?: string}} Measured
 */
/**
 * A job's result (the `result` of its kind in Jobs), or why it failed: `error`, with `unloaded`
 * when the tools could not be fetched (`error` is then the browser's).
 * @typedef {{type: 'job', job: number, result?: RawJobs[keyof RawJobs]['result'], error?: string, unloaded?: boolean}} JobReply
 */

/**
 * Every message the worker sends.
 * @typedef {Ready | Crashed | Described | Invalid | Progress | Done | Cancelled | ViewReply | CsvChunk
 *   | CsvFailed | Inspected | Compared | PinProgress | Pins | OverlayReply | Measured | JobReply} FromWorker
 */

/**
 * Every message the worker sends, as the page reads it: its messages of the core said.
 * @typedef {Spoken<FromWorker>} ToPage
 */

/**
 * The page's handlers of the messages no request waits on, by type.
 * @typedef {{[T in ToPage['type']]?: (data: Extract<ToPage, {type: T}>) => void}} Handlers
 */
