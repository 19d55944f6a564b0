//! A map's CSV, as `imlab robust` writes it and the page downloads it: its preamble, its header
//! and a row a cell.

use super::{rounded, Cell, Map, MAP_FIGURES};
use crate::text::csv;

/// The header of a map's CSV.
fn csv_header(map: &Map) -> String {
    let mut cols: Vec<String> = Vec::new();
    for a in &map.axes {
        let other = if a.key.starts_with("plant.") {
            "model"
        } else if a.key.starts_with("model.") {
            "plant"
        } else {
            "base"
        };
        cols.push(a.key.clone());
        cols.push(format!("{}_vs_{other}_pct", a.key));
    }
    cols.extend(
        [
            "runs",
            "ran_away",
            "inconsistent",
            "over_rating",
            "unsettled",
        ]
        .map(String::from),
    );
    for f in MAP_FIGURES {
        for s in ["min", "median", "max"] {
            cols.push(format!("{f}_{s}"));
        }
    }
    cols.push("scenario".to_string());
    cols.join(",") + "\n"
}

/// A number for the CSV: empty when it is not finite.
fn field(v: f64) -> String {
    if v.is_finite() {
        v.to_string()
    } else {
        String::new()
    }
}

/// One row of a map's CSV.
pub fn csv_row(map: &Map, cell: &Cell) -> String {
    let mut cols: Vec<String> = Vec::new();
    for ((a, v), &i) in map.axes.iter().zip(&cell.values).zip(&cell.index) {
        cols.push(field(*v));
        cols.push(field(rounded(100.0 * a.errors[i])));
    }
    cols.extend(
        [
            cell.runs,
            cell.ran_away,
            cell.inconsistent,
            cell.over_rating,
            cell.unsettled,
        ]
        .map(|n| n.to_string()),
    );
    for s in &cell.stats {
        cols.extend(s.iter().map(|v| field(*v)));
    }
    cols.push(cell.scenario.clone());
    csv::line(&cols) + "\n"
}

/// The whole CSV of a map: a comment line with the map's text and seeds, the header, one row a
/// cell. When `cells` holds only some of the map's cells (it was stopped), a second comment line
/// says how many.
pub fn map_csv(map: &Map, cells: &[Cell]) -> String {
    let mut out = csv_preamble(map);
    if cells.len() < map.cells.len() {
        let at = out.find('\n').map_or(0, |i| i + 1);
        out.insert_str(
            at,
            &format!(
                "# {} of {} cells: the map was stopped before the others ran\n",
                cells.len(),
                map.cells.len()
            ),
        );
    }
    for c in cells {
        out.push_str(&csv_row(map, c));
    }
    out
}

/// The comment line and header that start a map's CSV.
pub fn csv_preamble(map: &Map) -> String {
    format!("# {} over {}\n{}", map.scenario, map.text, csv_header(map))
}
