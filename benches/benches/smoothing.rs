//! Smoothing and timing a 100-node path at a quarter-cell spacing (`postproc`).
//!
//! The world is a 40 x 40 grid with three walls forming a serpentine corridor; the path is
//! 100 jittered nodes along the corridor, like a sampling planner's output. Each method of
//! `postproc::Smoothing` is measured end to end: input check, pruning, fitting, sampling at
//! 0.25 cell, checking every sample pair against an exact grid oracle, repairs, then timing
//! under v_max / omega_max / a_max. Run with `cargo bench -p hyplan-benches --bench smoothing`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_main};
use hyplan_core::Point2;
use postproc::{Limits, Smoothing, smooth_checked};

const W: usize = 40;
const SPACING: f64 = 0.25;

/// The serpentine grid: walls x in [10, 11) for y < 30, [20, 21) for y >= 10,
/// [30, 31) for y < 30.
fn blocked_cells() -> Vec<bool> {
    let mut b = vec![false; W * W];
    for j in 0..W {
        for i in 0..W {
            b[j * W + i] = (i == 10 && j < 30) || (i == 20 && j >= 10) || (i == 30 && j < 30);
        }
    }
    b
}

/// Exact segment check against closed unit cells, as `envmap`'s grid does it: row by row,
/// only the cells the segment's slice of that row can touch are tested (Liang-Barsky), so
/// the cost grows with the segment's length, not with its bounding box.
fn segment_free(blocked: &[bool], a: Point2, b: Point2) -> bool {
    let n = W as f64;
    let inside = |p: Point2| p.x >= 0.0 && p.y >= 0.0 && p.x <= n && p.y <= n;
    if !(inside(a) && inside(b)) {
        return false;
    }
    let d = b - a;
    // Cell k's closed span [k, k + 1] meets [lo, hi] exactly for k in [ceil(lo) - 1, floor(hi)].
    let span = |lo: f64, hi: f64| (lo.ceil() as i64 - 1, hi.floor() as i64);
    let (j0, j1) = span(a.y.min(b.y), a.y.max(b.y));
    for j in j0.max(0)..=j1.min(W as i64 - 1) {
        let y = j as f64;
        // The segment's x-range inside the closed row y in [j, j + 1].
        let (x_lo, x_hi) = if d.y == 0.0 {
            (a.x.min(b.x), a.x.max(b.x))
        } else {
            let ta = ((y - a.y) / d.y).clamp(0.0, 1.0);
            let tb = ((y + 1.0 - a.y) / d.y).clamp(0.0, 1.0);
            let (xa, xb) = (a.x + d.x * ta, a.x + d.x * tb);
            (xa.min(xb), xa.max(xb))
        };
        // Widened by a hair so that rounding in x_lo, x_hi never skips a touched cell.
        let (i0, i1) = span(x_lo - 1e-9, x_hi + 1e-9);
        for i in i0.max(0)..=i1.min(W as i64 - 1) {
            if blocked[j as usize * W + i as usize] && hits_cell(a, d, i as f64, y) {
                return false;
            }
        }
    }
    true
}

/// Whether the closed segment `a + t d`, t in [0, 1], meets the closed unit cell at (x, y).
fn hits_cell(a: Point2, d: nalgebra_free::Vector, x: f64, y: f64) -> bool {
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for (p, q) in [
        (-d.x, a.x - x),
        (d.x, x + 1.0 - a.x),
        (-d.y, a.y - y),
        (d.y, y + 1.0 - a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else if p < 0.0 {
            t0 = t0.max(q / p);
        } else {
            t1 = t1.min(q / p);
        }
    }
    t0 <= t1
}

/// The vector type of `Point2` differences, named without depending on nalgebra.
mod nalgebra_free {
    /// `Point2 - Point2`.
    pub type Vector = <hyplan_core::Point2 as std::ops::Sub>::Output;
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
    let blocked = blocked_cells();
    let path = hundred_nodes();
    assert_eq!(path.len(), 100);
    assert!(path.windows(2).all(|w| segment_free(&blocked, w[0], w[1])));
    let limits = Limits::new(1.0, 1.0, 0.5).expect("valid limits");

    let mut group = c.benchmark_group("smoothing");
    group.throughput(Throughput::Elements(path.len() as u64));
    for method in Smoothing::ALL {
        // Check the result once, outside the timed loop.
        let s = smooth_checked(&path, method, SPACING, |a, b| segment_free(&blocked, a, b))
            .expect("smoothing succeeds");
        assert!(
            s.points
                .windows(2)
                .all(|w| segment_free(&blocked, w[0], w[1]))
        );
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
                    let s = smooth_checked(black_box(path), method, SPACING, |a, b| {
                        segment_free(&blocked, a, b)
                    })
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
