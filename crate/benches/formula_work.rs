//! The price the work bound charges a law's operations against what they cost: for each kind of
//! term at its costliest argument, a formula of 40 such terms is evaluated (and its rate, by
//! forward mode, computed) side by side with a formula of 40 plain signals, whose value takes
//! one simple operation a term: the ratio of their times gives each term's cost in simple
//! operations. The table prints the
//! measured operations, those charged, and their ratio, which should stay at or below 1: a ratio
//! above it means the bound lets a law cost more than it says. Median of BENCH_RUNS (default 9)
//! alternating repetitions. Run with `cargo bench --bench formula_work`.

use imlab::control::formula::{index, Program, SIGNALS};
use std::hint::black_box;
use std::time::Instant;

/// Each term, at its costliest argument found (huge arguments for the sine and cosine, the
/// slowest paths of the power, subnormal and overflowing ones elsewhere).
const TERMS: [&str; 15] = [
    "x1h*x2h",
    "x1h/x2h",
    "sqrt(x1h)",
    "abs(x1h)",
    "sat(x1h, x2h)",
    "sin(1e300*x1h)",
    "cos(1e300*x1h)",
    "sin(1e22*x1h)",
    "exp(-745*x1h)",
    "ln(1e-310*x1h)",
    "tanh(0.1*x1h)",
    "atan2(1e-300*x1h, 1e300*x2h)",
    "x1h^1.5",
    "x1h^-1.5",
    "(1e300*x1h)^(1e-300*x2h)",
];

const REPEAT: usize = 40;
const EVALS: usize = 100_000;

/// Seconds for EVALS evaluations of `p` (its rate with `rate`), the signals moving a little.
fn seconds(p: &Program, rate: bool) -> f64 {
    let mut s = [0.5f64; SIGNALS];
    s[index("x1h").expect("a name")] = 0.37;
    let r = [1.0f64; SIGNALS];
    let t = Instant::now();
    let mut acc = 0.0;
    for i in 0..EVALS {
        s[0] = i as f64 * 1e-9;
        acc += if rate {
            p.eval_rate(black_box(&s), &r)
        } else {
            p.eval(black_box(&s))
        };
    }
    black_box(acc);
    t.elapsed().as_secs_f64()
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let runs: usize = std::env::var("BENCH_RUNS")
        .ok()
        .and_then(|t| t.parse().ok())
        .unwrap_or(9);
    let formula = |term: &str| vec![term; REPEAT].join(" + ");
    let plain = Program::parse(&formula("x1h"), 1).expect("parses");
    println!("| term | measured / charged, value | measured / charged, rate |");
    println!("|---|---|---|");
    for term in TERMS {
        let p = Program::parse(&formula(term), 1).expect("parses");
        let row: Vec<String> = [false, true]
            .into_iter()
            .map(|rate| {
                let ratios = (0..runs)
                    .map(|_| seconds(&p, rate) / seconds(&plain, false))
                    .collect();
                let charged = if rate { p.rate_work() } else { p.work() };
                let measured = median(ratios) * plain.work() as f64 / REPEAT as f64;
                let charged = charged as f64 / REPEAT as f64;
                format!("{measured:.1} / {charged:.0} = {:.2}", measured / charged)
            })
            .collect();
        println!("| `{term}` | {} | {} |", row[0], row[1]);
    }
}
