//! Smoothing and timing a 100-node path at a quarter-cell spacing (`postproc`).
//!
//! The world is a 40 x 40 grid with three walls forming a serpentine corridor; the path is
//! 100 jittered nodes along the corridor, like a sampling planner's output. Each method of
//! `postproc::Smoothing` is measured end to end: input check, pruning, fitting, sampling at
//! 0.25 cell, checking every sample pair against the grid map's exact segment check,
//! repairs, then timing under v_max / omega_max / a_max. Run with
//! `cargo bench -p hyplan-benches --bench smoothing`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_main};
use envmap::GridMap;
use hyplan_core::{Point2, Workspace, Zone};
use postproc::{Limits, Smoothing, smooth_checked};

const W: usize = 40;
const SPACING: f64 = 0.25;

/// The serpentine grid of unit cells: walls x in [10, 11) for y < 30, [20, 21) for
/// y >= 10, [30, 31) for y < 30. Its exact segment check is the smoothing oracle.
fn serpentine() -> GridMap {
    let mut map = GridMap::filled(W, W, Zone::Free).expect("a valid size");
    for j in 0..W {
        for i in 0..W {
            if (i == 10 && j < 30) || (i == 20 && j >= 10) || (i == 30 && j < 30) {
                map.set_cell_zone(i, j, Zone::Forbidden);
            }
        }
    }
    map
}

/// 100 nodes along the corridor's centre line, jittered by up to 0.4 cell.
fn hundred_nodes() -> Vec<Point2> {
    let centre = [
        Point2::new(5.0, 5.0),
        Point2::new(5.0, 35.0),
        Point2::new(15.5, 35.0),
        Point2::new(15.5, 5.0),
        Point2::new(25.5, 5.0),
        Point2::new(25.5, 35.0),
        Point2::new(35.0, 35.0),
        Point2::new(35.0, 5.0),
    ];
    let len = hyplan_core::path_length(&centre);
    (0..100)
        .map(|k| {
            let mut s = len * f64::from(k) / 99.0;
            let mut i = 0;
            while i + 2 < centre.len() && s > (centre[i + 1] - centre[i]).norm() {
                s -= (centre[i + 1] - centre[i]).norm();
                i += 1;
            }
            let dir = (centre[i + 1] - centre[i]).normalize();
            let p = centre[i] + dir * s;
            if k == 0 || k == 99 {
                return p;
            }
            let jitter = 0.4 * (f64::from(k) * 2.39).sin();
            Point2::new(p.x + jitter, p.y - jitter)
        })
        .collect()
}

/// The `smoothing` group: every method on the same 100-node path.
fn smoothing(c: &mut Criterion) {
    let map = serpentine();
    let segment_free = |a, b| map.segment_free(a, b);
    let path = hundred_nodes();
    assert_eq!(path.len(), 100);
    assert!(path.windows(2).all(|w| segment_free(w[0], w[1])));
    let limits = Limits::new(1.0, 1.0, 0.5).expect("valid limits");

    let mut group = c.benchmark_group("smoothing");
    group.throughput(Throughput::Elements(path.len() as u64));
    for method in Smoothing::ALL {
        // Check the result once, outside the timed loop.
        let s = smooth_checked(&path, method, SPACING, segment_free).expect("smoothing succeeds");
        assert!(s.points.windows(2).all(|w| segment_free(w[0], w[1])));
        let t = s.time(&limits).expect("timing succeeds");
        assert!(t.transfer_time >= s.length() / limits.v_max);
        eprintln!(
            "{method}: {} nodes -> {} samples, {} repairs, length {:.2}, transfer {:.2} s",
            path.len(),
            s.points.len(),
            s.repairs.len(),
            s.length(),
            t.transfer_time
        );
        group.bench_with_input(
            BenchmarkId::new(method.name(), path.len()),
            &path,
            |b, path| {
                b.iter(|| {
                    let s = smooth_checked(black_box(path), method, SPACING, segment_free)
                        .expect("smoothing succeeds");
                    black_box(s.time(&limits).expect("timing succeeds").transfer_time)
                });
            },
        );
    }
    group.finish();
}

/// The criterion entry points (the macro's generated function carries no doc).
#[allow(missing_docs)]
mod entry {
    criterion::criterion_group!(benches, super::smoothing);
}
criterion_main!(entry::benches);
