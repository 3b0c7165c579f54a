//! Nearest-neighbour queries: `sampling::NearestIndex` (the workspace's k-d tree) against
//! its peer, kiddo 5's mutable k-d tree (which it replaced; leaves of 64 points, as ours),
//! and a linear scan, in one group so the ratios come from one run. Sizes in the benchmark
//! id; 1000 queries per iteration (`Throughput::Elements`).

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_main};
use hyplan_core::Point2;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use sampling::NearestIndex;

/// kiddo's mutable tree with our leaf size.
type Kiddo = kiddo::float::kdtree::KdTree<f64, u64, 2, 64, u32>;

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
        let mut kiddo = Kiddo::new();
        for (i, p) in pts.iter().enumerate() {
            kiddo.add(&[p.x, p.y], i as u64);
        }
        group.bench_with_input(BenchmarkId::new("nearest_index", n), &n, |b, _| {
            b.iter(|| {
                let mut acc = 0;
                for &q in &queries {
                    acc += index.nearest(black_box(q)).unwrap().0;
                }
                acc
            });
        });
        group.bench_with_input(BenchmarkId::new("kiddo", n), &n, |b, _| {
            b.iter(|| {
                let mut acc = 0;
                for &q in &queries {
                    let q = black_box(q);
                    acc += kiddo
                        .nearest_one::<kiddo::SquaredEuclidean>(&[q.x, q.y])
                        .item;
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
    group.bench_function(BenchmarkId::new("nearest_index", QUERIES), |b| {
        b.iter(|| {
            let mut index = NearestIndex::with_capacity(QUERIES);
            for &p in &pts {
                index.insert(black_box(p));
            }
            index.len()
        });
    });
    group.bench_function(BenchmarkId::new("kiddo", QUERIES), |b| {
        b.iter(|| {
            let mut tree = Kiddo::with_capacity(QUERIES);
            for (i, &p) in pts.iter().enumerate() {
                let p = black_box(p);
                tree.add(&[p.x, p.y], i as u64);
            }
            tree.size()
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
