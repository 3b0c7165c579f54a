//! The constants of `sim::DetectorCost`: this machine's time for the operations one
//! iteration of `rrt_exploration`'s detectors performs, done the same way in Rust.
//!
//! - a copy of a map's cells (`std::vector<signed char>` by value: allocate, `memcpy`,
//!   free), for maps of 10^4 to 10^6 cells; a least-squares line gives the fixed cost
//!   and the cost per cell;
//! - `Nearest(V, x)`: the node list copied by value (one heap vector of two floats per
//!   node) and scanned for the nearest, plus two line points per node for the
//!   published marker, for 100 to 10,000 nodes; the slope is the cost per node.
//!
//! Each size is timed as the median of 15 rounds. Run with
//! `cargo run --release -p hyplan-benches --example detector_cost`.

use std::hint::black_box;
use std::time::Instant;

/// Median seconds per call of `f` over 15 rounds of `reps` calls.
fn median_per_call(reps: usize, mut f: impl FnMut()) -> f64 {
    let mut rounds: Vec<f64> = (0..15)
        .map(|_| {
            let t = Instant::now();
            for _ in 0..reps {
                f();
            }
            t.elapsed().as_secs_f64() / reps as f64
        })
        .collect();
    rounds.sort_by(f64::total_cmp);
    rounds[rounds.len() / 2]
}

/// Least-squares intercept and slope of `y` against `x`.
fn fit(points: &[(f64, f64)]) -> (f64, f64) {
    let n = points.len() as f64;
    let (sx, sy) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), &(x, y)| (a + x, b + y));
    let (mx, my) = (sx / n, sy / n);
    let (sxy, sxx) = points.iter().fold((0.0, 0.0), |(a, b), &(x, y)| {
        (a + (x - mx) * (y - my), b + (x - mx) * (x - mx))
    });
    let slope = sxy / sxx;
    (my - slope * mx, slope)
}

fn main() {
    println!("map copies (cells, ns per copy):");
    let mut copies = Vec::new();
    for cells in [10_000usize, 50_000, 100_000, 200_000, 500_000, 1_000_000] {
        let map: Vec<i8> = (0..cells).map(|k| (k % 3) as i8 - 1).collect();
        let reps = (20_000_000 / cells).max(20);
        let t = median_per_call(reps, || {
            let copy = black_box(&map).clone();
            black_box(copy[cells / 2]);
        });
        println!("  {cells:>9} {:>10.1}", t * 1e9);
        copies.push((cells as f64, t));
    }
    let (copy, cell) = fit(&copies);
    println!("nearest by value (nodes, ns per call):");
    let mut nearest = Vec::new();
    for nodes in [100usize, 1_000, 3_000, 10_000] {
        let tree: Vec<Vec<f32>> = (0..nodes)
            .map(|k| vec![(k % 97) as f32 * 0.1, (k / 97) as f32 * 0.1])
            .collect();
        let reps = (2_000_000 / nodes).max(20);
        let t = median_per_call(reps, || {
            let v = black_box(&tree).clone();
            let x = [3.3f32, 4.4];
            let best = v
                .iter()
                .map(|p| ((p[0] - x[0]).powi(2) + (p[1] - x[1]).powi(2)).sqrt())
                .fold(f32::INFINITY, f32::min);
            let line: Vec<[f32; 3]> = v
                .iter()
                .flat_map(|p| [[p[0], p[1], 0.0], [p[0], p[1], 0.0]])
                .collect();
            black_box((best, line.len()));
        });
        println!("  {nodes:>9} {:>10.1}", t * 1e9);
        nearest.push((nodes as f64, t));
    }
    let (iteration, node) = fit(&nearest);
    println!(
        "DetectorCost: copy = {:.1} ns (fitted {:.1}), cell = {:.4} ns, node = {:.1} ns, iteration = {:.1} ns",
        copy.max(0.0) * 1e9,
        copy * 1e9,
        cell * 1e9,
        node * 1e9,
        iteration.max(0.0) * 1e9
    );
}
