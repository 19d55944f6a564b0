//! The map's plan, its bound, its cells and its CSV.

use super::*;

fn step() -> Scenario {
    Scenario::parse("v=1&preset=step").unwrap()
}

#[test]
fn a_relative_axis_is_read_against_the_other_side() {
    let a = Axis::parse(&step(), "plant.rr=-10%..+10%:3").unwrap();
    assert_eq!(a.values.len(), 3);
    assert!((a.values[0] - 4.95 * 0.9).abs() < 1e-12 && (a.values[2] - 4.95 * 1.1).abs() < 1e-12);
    assert!((a.errors[1]).abs() < 1e-15);
    let m = Axis::parse(&step(), "model.j=0.016..0.024:2").unwrap();
    assert!((m.errors[0] + 0.2).abs() < 1e-12 && (m.errors[1] - 0.2).abs() < 1e-12);
}

#[test]
fn bad_axes_are_refused_naming_the_input() {
    for (text, says) in [
        ("kx=1..2:3", "kx is not a scenario field"),
        ("controller=1..2:3", "is not a number"),
        ("ifoc.bw_w=1..2:3", "no effect in this scenario"),
        ("plant.rr=-10%..5:3", "both be values or both percentages"),
        ("plant.rr=1..2:0", "N '0'"),
        ("plant.rr=2..1:3", "above HI"),
        ("plant.rr=x..1:3", "LO 'x'"),
        ("plant.np=1..3:3", "whole numbers"),
        ("seed=1..3:3", "whole numbers"),
        ("plant.rr", "expected KEY=LO..HI:N"),
    ] {
        let e = Axis::parse(&step(), text).unwrap_err();
        assert!(e.to_string().contains(says), "{text}: {e}");
    }
    let e = Map::parse(&step(), "plant.rr=-1000%..0%:3").unwrap_err();
    assert!(e.to_string().contains("plant.rr="), "{e}");
}

#[test]
fn every_figure_a_map_keeps_is_a_figure_of_the_report() {
    // The bindings label the map's figures from the report's table.
    for name in MAP_FIGURES {
        assert!(crate::record::figure_info(name).is_some(), "{name}");
    }
}

#[test]
fn maps_that_would_be_silently_wrong_are_refused() {
    let no_load = Scenario::parse("v=1&preset=step&plant.t0=0&model.t0=0").unwrap();
    let e = Axis::parse(&no_load, "plant.t0=-10%..10%:3").unwrap_err();
    assert!(e.to_string().contains("model.t0 is 0"), "{e}");
    let e = Map::parse(&step(), "plant.rr=-10%..10%:3;model.rr=4..5:2").unwrap_err();
    assert!(e.to_string().contains("both sides of one parameter"), "{e}");
    let e = Map::parse(&step(), "plant.rr=-10%..10%:3;seeds=1..2;seeds=3..4").unwrap_err();
    assert!(e.to_string().contains("twice"), "{e}");
    let e = Axis::parse(&step(), "plant.rr=+-5%..5%:3").unwrap_err();
    assert!(e.to_string().contains("LO '+-5%'"), "{e}");
    let e = Map::parse(
        &step(),
        "plant.rr=-10%..10%:101;model.j=-20%..20%:101;seeds=1..11",
    )
    .unwrap_err();
    assert!(e.to_string().contains("112211 runs"), "{e}");
    // Values and their errors are written as a user would type them.
    let m = Map::parse(&step(), "model.j=0.016..0.024:5;seeds=1").unwrap();
    assert!(
        m.cells[1].scenario.ends_with("model.j=0.018"),
        "{}",
        m.cells[1].scenario
    );
    assert_eq!(
        m.axes[0].label,
        Arg::from(
            Message::new("map-axis-unit")
                .text("key", "model.j")
                .text("unit", "kg m²")
        )
    );
    let m = Map::parse(&step(), "plant.rr=-10%..10%:21;seeds=1").unwrap();
    let cell = summarise(&m.cells[3], &[]);
    assert!(
        csv_row(&m, &cell).starts_with("4.6035,-7,0,"),
        "{}",
        csv_row(&m, &cell)
    );
}

#[test]
fn a_stopped_map_says_how_many_cells_its_csv_holds() {
    let m = Map::parse(&step(), "plant.rr=-10%..10%:3;seeds=1").unwrap();
    let cells: Vec<Cell> = m.cells[..1].iter().map(|c| summarise(c, &[])).collect();
    let csv = map_csv(&m, &cells);
    assert_eq!(
        csv.lines().nth(1),
        Some("# 1 of 3 cells: the map was stopped before the others ran")
    );
    assert!(!map_csv(
        &m,
        &m.cells
            .iter()
            .map(|c| summarise(c, &[]))
            .collect::<Vec<_>>()
    )
    .contains("stopped"));
}

#[test]
fn a_map_past_the_work_bound_is_refused_with_what_it_needs() {
    let long = Scenario::parse("v=1&preset=rr-mismatch&duration=20").unwrap();
    let e = Map::parse(&long, "plant.rr=-10%..10%:101;seeds=1..100")
        .unwrap_err()
        .to_string();
    assert!(e.contains("plant steps") && e.contains("400000000"), "{e}");
}

#[test]
fn a_map_counts_the_work_of_its_laws() {
    // Each step's law the paper's plus 100 sines of a huge argument: at 0.56 s, each run takes
    // more than 99 % of the laws' work a single run may take; 40 such runs fit, not 41.
    let sines = ["sin(1e300*x1h)"; 100].join(" + ");
    let laws: Vec<(String, String)> = (0..4)
        .map(|i| {
            let law = crate::control::law::PAPER[i];
            (format!("law.v{}", i + 1), format!("{law} + 0*({sines})"))
        })
        .collect();
    let mut fields = vec![("duration".to_string(), "0.56".to_string())];
    fields.extend(laws);
    let base = Scenario::parse(&crate::scenario::compose("step", &fields)).unwrap();
    let per_run = base.law_work().unwrap();
    assert!(
        per_run > MAX_LAW_WORK * 99 / 100 && per_run <= MAX_LAW_WORK,
        "{per_run}"
    );
    let m = Map::parse(&base, "plant.rr=-10%..10%:20;seeds=1..2").unwrap();
    assert_eq!(m.law_work, 40 * per_run);
    let e = Map::parse(&base, "plant.rr=-10%..10%:41;seeds=1")
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("the map's own laws take") && e.contains("use at most 40 runs"),
        "{e}"
    );
    // Without laws, the same map counts none.
    assert_eq!(
        Map::parse(&step(), "plant.rr=-10%..10%:41;seeds=1")
            .unwrap()
            .law_work,
        0
    );
}

#[test]
fn cells_run_the_last_axis_fastest_and_the_text_round_trips() {
    let m = Map::parse(
        &step(),
        "plant.rr=-10%..10%:3;model.j=0.016..0.024:2;seeds=3..4",
    )
    .unwrap();
    assert_eq!(m.cells.len(), 6);
    assert_eq!(m.seeds, vec![3, 4]);
    assert_eq!(m.cells[1].values[0], m.cells[0].values[0]);
    assert!(m.cells[1].scenario.contains("model.j=0.024"));
    let again = Map::parse(&step(), &m.text).unwrap();
    assert_eq!(again, m);
}

#[test]
fn the_summary_counts_runaways_and_takes_statistics_over_completed_runs() {
    let m = Map::parse(&step(), "plant.rr=-10%..10%:1;seeds=1..3").unwrap();
    let run = |seed, v: f64, failure: Option<&str>| MapRun {
        seed,
        figures: vec![v; MAP_FIGURES.len()],
        ran_away: failure.is_some(),
        inconsistent: false,
        over_rating: v > 2.0,
        unsettled: v < 2.0,
        failure: failure.map(String::from),
    };
    let mut away = run(4, -50.0, None);
    away.ran_away = true;
    let c = summarise(
        &m.cells[0],
        &[
            run(1, 3.0, None),
            run(2, 1.0, None),
            run(3, 1e9, Some("diverged")),
            away,
        ],
    );
    assert_eq!((c.runs, c.ran_away), (4, 2));
    // What holding cost is counted over the runs that held: the run at 3 passed the rating,
    // the one at 1 had not settled; the diverged run's 1e9 counts for neither.
    assert_eq!((c.over_rating, c.unsettled), (1, 1));
    // Neither the diverged run nor the one that ran away enters the statistics.
    assert_eq!(c.stats[0], [1.0, 2.0, 3.0]);
}

#[test]
fn the_paper_step_runs_away_with_the_motor_r_r_ten_percent_high_and_not_when_exact() {
    let m = Map::parse(&step(), "plant.rr=0%..10%:2;seeds=1..2").unwrap();
    let rows: Vec<Cell> = m
        .cells
        .iter()
        .map(|c| {
            let runs: Vec<MapRun> = m
                .seeds
                .iter()
                .map(|&s| map_run(&c.scenario, s).unwrap())
                .collect();
            summarise(c, &runs)
        })
        .collect();
    assert_eq!(rows[0].ran_away, 0);
    assert_eq!(rows[1].ran_away, 2);
    let csv = map_csv(&m, &rows);
    assert!(csv.starts_with("# v=1&preset=step over plant.rr=0%..10%:2;seeds=1..2\nplant.rr,plant.rr_vs_model_pct,runs,"));
    assert_eq!(csv.lines().count(), 4);
}

#[test]
fn a_gain_or_the_filters_tuning_is_an_axis_read_against_the_base() {
    let base = step();
    let k1 = value_of(&base, "k1").unwrap().0;
    let m = Map::parse(&base, "k1=1100..1500:3;seeds=1").unwrap();
    let ends: Vec<&str> = m.cells.iter().map(|c| c.scenario.as_str()).collect();
    assert!(ends[1].ends_with("k1=1300"), "{ends:?}");
    assert!((m.axes[0].errors[2] - (1500.0 / k1 - 1.0)).abs() < 1e-9);
    assert_eq!(
        m.axes[0].label,
        Arg::from(
            Message::new("map-axis-unit")
                .text("key", "k1")
                .text("unit", "1/s")
        )
    );
    let r = Axis::parse(&base, "ekf.r_std=-50%..+50%:3").unwrap();
    let q = value_of(&base, "ekf.r_std").unwrap().0;
    assert_eq!(r.values, vec![rounded(q * 0.5), q, rounded(q * 1.5)]);
    assert_eq!(r.errors[0], -0.5);
    assert_eq!(
        r.label,
        Arg::from(Message::new("map-axis-against-base").text("key", "ekf.r_std"))
    );
    // Under IFOC the backstepping gains act on nothing: a map of one would run the same cells.
    let ifoc = Scenario::parse("v=1&preset=ifoc-step").unwrap();
    let e = Axis::parse(&ifoc, "k1=1000..1400:3").unwrap_err();
    assert_eq!(e.id, "map-axis-inactive");
    // Two axes of one field are refused, as two sides of one parameter are.
    let e = Map::parse(&base, "k1=1..2:2;k1=3..4:2").unwrap_err();
    assert_eq!(e.id, "map-axes-repeated");
}
