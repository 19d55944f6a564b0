//! Scenario parsing time against input length, with criterion: linear up to the 16 KiB cap, and a
//! 1 MB input refused at once. Strict (`Scenario::parse`) and lenient (`parse_lenient`) parsers;
//! criterion's throughput is input bytes per second.
//!
//! Run with `cargo bench --bench codec`; one parser with `cargo bench --bench codec -- lenient`.

use criterion::{BenchmarkId, Criterion, Throughput};
use imlab::scenario::{Scenario, MAX_SCENARIO_BYTES};
use std::hint::black_box;
use std::time::Duration;

/// `v=1&preset=step` followed by distinct unknown keys up to `bytes` long: every piece is looked
/// up, and the lenient parser keeps going past each one.
fn input(bytes: usize) -> String {
    let mut text = "v=1&preset=step".to_string();
    let mut i = 0;
    while text.len() < bytes {
        text.push_str(&format!("&key{i}=1"));
        i += 1;
    }
    text.truncate(bytes);
    text
}

fn parse(c: &mut Criterion) {
    let mut group = c.benchmark_group("codec");
    group
        .sample_size(20)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(1));
    for bytes in [1 << 10, 4 << 10, MAX_SCENARIO_BYTES, 1 << 20] {
        let text = input(bytes);
        group.throughput(Throughput::Bytes(bytes as u64));
        group.bench_with_input(BenchmarkId::new("strict", bytes), &text, |b, text| {
            b.iter(|| Scenario::parse(black_box(text)).is_ok());
        });
        group.bench_with_input(BenchmarkId::new("lenient", bytes), &text, |b, text| {
            b.iter(|| Scenario::parse_lenient(black_box(text)).is_ok());
        });
    }
    group.finish();
}

// A plain main rather than `criterion_group!`, whose generated function has no doc comment.
fn main() {
    let mut c = Criterion::default().without_plots().configure_from_args();
    parse(&mut c);
    c.final_summary();
}
