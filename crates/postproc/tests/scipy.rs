//! PCHIP against scipy's `PchipInterpolator` (reference numbers in
//! `tests/data/pchip_scipy.json`, produced once by `tests/data/pchip_scipy.py`).

use hyplan_core::Point2;
use postproc::Pchip;
use serde_json::Value;

fn pairs(v: &Value) -> Vec<[f64; 2]> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|p| [p[0].as_f64().unwrap(), p[1].as_f64().unwrap()])
        .collect()
}

fn floats(v: &Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

/// 1e-9, relative to the magnitude for values above 1 (the millimetre-scale set).
fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * b.abs().max(1.0)
}

#[test]
fn pchip_matches_scipy() {
    let text = include_str!("data/pchip_scipy.json");
    let doc: Value = serde_json::from_str(text).unwrap();
    let sets = doc["datasets"].as_object().unwrap();
    assert!(sets.len() >= 6);
    for (name, set) in sets {
        let nodes: Vec<Point2> = pairs(&set["nodes"])
            .iter()
            .map(|p| Point2::new(p[0], p[1]))
            .collect();
        let c = Pchip::new(&nodes).unwrap();
        for (k, (&s, &want)) in c.knots().iter().zip(&floats(&set["knots"])).enumerate() {
            assert!(close(s, want), "{name}: knot {k}: {s} vs {want}");
        }
        for (k, (d, want)) in c.slopes().iter().zip(pairs(&set["slopes"])).enumerate() {
            assert!(
                close(d.x, want[0]) && close(d.y, want[1]),
                "{name}: slope {k}: {d:?} vs {want:?}"
            );
            // The derivative at a knot is the slope there.
            let at = c.derivative(c.knots()[k]);
            assert!(
                close(at.x, want[0]) && close(at.y, want[1]),
                "{name}: derivative at knot {k}"
            );
        }
        let queries = floats(&set["queries"]);
        for (what, key) in [("value", "values"), ("d1", "d1"), ("d2", "d2")] {
            for (&s, want) in queries.iter().zip(pairs(&set[key])) {
                let got = match what {
                    "value" => c.eval(s).coords,
                    "d1" => c.derivative(s),
                    _ => c.second_derivative(s),
                };
                // Second derivatives carry 1/h^2: compare them a little more loosely.
                let ok = if what == "d2" {
                    (got.x - want[0]).abs() <= 1e-8 * want[0].abs().max(1.0)
                        && (got.y - want[1]).abs() <= 1e-8 * want[1].abs().max(1.0)
                } else {
                    close(got.x, want[0]) && close(got.y, want[1])
                };
                assert!(ok, "{name}: {what} at s = {s}: {got:?} vs {want:?}");
            }
        }
    }
}
