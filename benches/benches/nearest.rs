//! Nearest-neighbour queries: `sampling::NearestIndex` (kiddo k-d tree) against a linear
//! scan, in one group so the ratio comes from one run. Sizes in the benchmark id; 1000
//! queries per iteration (`Throughput::Elements`).

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_main};
use hyplan_core::Point2;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use sampling::NearestIndex;

const QUERIES: usize = 1000;

fn points(n: usize, seed: u64) -> Vec<Point2> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..n)
        .map(|_| Point2::new(rng.random::<f64>() * 1000.0, rng.random::<f64>() * 1000.0))
        .collect()
}

fn linear_nearest(points: &[Point2], q: Point2) -> usize {
    let mut best = (0, f64::INFINITY);
    for (i, p) in points.iter().enumerate() {
        let d = (p - q).norm_squared();
        if d < best.1 {
            best = (i, d);
        }
    }
    best.0
}

fn bench_nearest(c: &mut Criterion) {
    let mut group = c.benchmark_group("nearest");
    group.throughput(Throughput::Elements(QUERIES as u64));
    let queries = points(QUERIES, 2);
    for n in [100_usize, 1_000, 10_000, 100_000] {
        let pts = points(n, 1);
        let mut index = NearestIndex::with_capacity(n);
        for &p in &pts {
            index.insert(p);
        }
        // Checked once, outside the timed loop: the index agrees with the scan.
        for &q in &queries[..100] {
            let (id, d) = index.nearest(q).unwrap();
            let lin = linear_nearest(&pts, q);
            assert!(
                (d - (pts[lin] - q).norm()).abs() < 1e-12,
                "index {id} vs scan {lin}"
            );
        }
        group.bench_with_input(BenchmarkId::new("kiddo_index", n), &n, |b, _| {
            b.iter(|| {
                let mut acc = 0;
                for &q in &queries {
                    acc += index.nearest(black_box(q)).unwrap().0;
                }
                acc
            });
        });
        if n <= 10_000 {
            group.bench_with_input(BenchmarkId::new("linear_scan", n), &n, |b, _| {
                b.iter(|| {
                    let mut acc = 0;
                    for &q in &queries {
                        acc += linear_nearest(&pts, black_box(q));
                    }
                    acc
                });
            });
        }
    }
    group.finish();

    // Insertion (the RRT loop inserts one node per iteration), 1000 points per iteration.
    let mut group = c.benchmark_group("nearest_insert");
    group.throughput(Throughput::Elements(QUERIES as u64));
    let pts = points(QUERIES, 3);
    group.bench_function(BenchmarkId::new("kiddo_index", QUERIES), |b| {
        b.iter(|| {
            let mut index = NearestIndex::with_capacity(QUERIES);
            for &p in &pts {
                index.insert(black_box(p));
            }
            index.len()
        });
    });
    group.finish();
}

/// The criterion entry points (the macro's generated function carries no doc).
#[allow(missing_docs)]
mod entry {
    criterion::criterion_group!(benches, super::bench_nearest);
}
criterion_main!(entry::benches);
