//! envmap's hot paths: the seed-000 pipeline on a camera-sized picture, the exact EDT at
//! three sizes, and `segment_free` on short and long segments on small and large maps.
//!
//! Run with `cargo bench -p hyplan-benches --bench envmap`.
//!
//! - `pipeline/1280x960`: `Pipeline::default()` (threshold 100, exact obstacles, 20-cell
//!   band) and with `rectangles`, on `envmap::demo_room(1280, 960)`: binarize,
//!   8-connected components, rectangles, EDT, zones. Target <= 20 ms.
//! - `edt/N`: `distance_transform` of an N x N mask (the demo room binarized at N x N).
//!   Linear time: doubling N should cost about 4x. Target for 4096: <= 400 ms.
//! - `inflation/{inflate,full}/N`: Nav2 costs of an N x N mask (the demo room) at 0.1 m
//!   per cell with sim's costmap radii (inscribed 0.27 m, inflation 0.55 m), by the bounded
//!   `Inflation::inflate` and by `costs` of the full transform (equal, checked once).
//! - `segment_free/{map}/{len}`: a segment of about `len` cells on an empty map of 64 x 64
//!   or 4096 x 4096 cells; the cost should follow `len`, not the map size.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_main};
use envmap::{GridMap, Mask, Pipeline, binarize, demo_room, distance_transform};
use hyplan_core::{Point2, Workspace, Zone};

fn pipeline(c: &mut Criterion) {
    let room = demo_room(1280, 960);
    let cells = (room.width() * room.height()) as u64;
    // Checked once outside the timed loop: the room's furniture is found.
    let out = Pipeline::default().run(&room).unwrap();
    assert_eq!(out.components.len(), 16, "demo room components");
    let [free, risk, forbidden] = out.map.zone_counts();
    assert!(free > 0 && risk > 0 && forbidden > 0);
    let mut g = c.benchmark_group("pipeline");
    g.throughput(Throughput::Elements(cells));
    g.sample_size(20);
    g.bench_function(BenchmarkId::new("exact", "1280x960"), |b| {
        b.iter(|| Pipeline::default().run(black_box(&room)).unwrap())
    });
    let rect = Pipeline {
        rectangles: true,
        ..Pipeline::default()
    };
    g.bench_function(BenchmarkId::new("rectangles", "1280x960"), |b| {
        b.iter(|| rect.run(black_box(&room)).unwrap())
    });
    g.finish();
}

fn edt(c: &mut Criterion) {
    let mut g = c.benchmark_group("edt");
    g.sample_size(10);
    for n in [1024usize, 2048, 4096] {
        let mask: Mask = binarize(&demo_room(n, n), 100, false);
        // Checked once: an obstacle cell is at 0, a cell next to one at 1.
        let d = distance_transform(&mask);
        let (i, j) = (0..n * n)
            .map(|k| (k % n, k / n))
            .find(|&(i, j)| mask.get(i, j) && i > 0 && !mask.get(i - 1, j))
            .unwrap();
        assert_eq!((d.cell_dist_sq(i, j), d.cell_dist_sq(i - 1, j)), (0, 1));
        g.throughput(Throughput::Elements((n * n) as u64));
        g.bench_with_input(BenchmarkId::from_parameter(n), &mask, |b, mask| {
            b.iter(|| distance_transform(black_box(mask)))
        });
    }
    g.finish();
}

fn inflation(c: &mut Criterion) {
    let mut g = c.benchmark_group("inflation");
    g.sample_size(20);
    let inf = envmap::Inflation {
        inscribed_radius: 0.27,
        inflation_radius: 0.55,
        cost_scaling_factor: 10.0,
    };
    for n in [240usize, 1024] {
        let mask: Mask = binarize(&demo_room(n, n), 100, false);
        assert_eq!(
            inf.inflate(&mask, 0.1).unwrap(),
            inf.costs(&distance_transform(&mask), 0.1).unwrap()
        );
        g.bench_with_input(BenchmarkId::new("inflate", n), &mask, |b, mask| {
            b.iter(|| inf.inflate(black_box(mask), 0.1))
        });
        g.bench_with_input(BenchmarkId::new("full", n), &mask, |b, mask| {
            b.iter(|| inf.costs(&distance_transform(black_box(mask)), 0.1))
        });
    }
    g.finish();
}

fn segment_free(c: &mut Criterion) {
    let mut g = c.benchmark_group("segment_free");
    for side in [64usize, 4096] {
        let map = GridMap::filled(side, side, Zone::Free).unwrap();
        for len in [4.0f64, 60.0] {
            // A shallow diagonal from near the centre: about len + len / 3 cells.
            let a = Point2::new(side as f64 / 2.0 - 30.3, side as f64 / 2.0 - 10.1);
            let b = Point2::new(a.x + len, a.y + len / 3.0);
            let mut crossed = 0u64;
            map.segment_cells(a, b, |_, _| {
                crossed += 1;
                true
            });
            assert!(map.segment_free(a, b));
            g.throughput(Throughput::Elements(crossed));
            g.bench_with_input(
                BenchmarkId::new(format!("{side}x{side}"), format!("len{len}")),
                &(a, b),
                |bench, &(a, b)| bench.iter(|| map.segment_free(black_box(a), black_box(b))),
            );
        }
    }
    // A long segment across the large map: 4000 cells.
    let map = GridMap::filled(4096, 4096, Zone::Free).unwrap();
    let (a, b) = (Point2::new(40.5, 100.25), Point2::new(4040.5, 1300.75));
    assert!(map.segment_free(a, b));
    let mut crossed = 0u64;
    map.segment_cells(a, b, |_, _| {
        crossed += 1;
        true
    });
    g.throughput(Throughput::Elements(crossed));
    g.bench_function(BenchmarkId::new("4096x4096", "len4000"), |bench| {
        bench.iter(|| map.segment_free(black_box(a), black_box(b)))
    });
    g.finish();
}

fn benches() {
    let mut c = Criterion::default().configure_from_args();
    pipeline(&mut c);
    edt(&mut c);
    inflation(&mut c);
    segment_free(&mut c);
}

criterion_main!(benches);
