//! Shared fixtures.

use std::path::PathBuf;

use std::ops::Range;

use envmap::GridMap;
use hyplan_core::{Point2, Zone};

/// Seed of the random-grid tests.
pub const SEED: u64 = 0x5eed_0003;

/// The repository's `data` folder (public maps with their licences, `data/README.md`).
pub fn data_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../data")
}

/// The benchmark peers' generated maps, `data/generated`.
pub fn peer_maps_dir() -> PathBuf {
    data_dir().join("generated")
}

/// Reads a MovingAI `.map` with envmap's loader; a missing file fails the test with its
/// path (the error names it).
pub fn load_movingai(path: &std::path::Path) -> GridMap {
    envmap::read_movingai(path).unwrap_or_else(|e| panic!("{e}"))
}

/// Whether every consecutive pair of cells is one legal 8-connected move without corner
/// cutting on `map`, and every cell is free.
pub fn legal_moves(map: &GridMap, cells: &[(usize, usize)]) -> bool {
    cells.iter().all(|&(i, j)| map.cell_free(i, j))
        && cells.windows(2).all(|w| {
            let ((a, b), (c, d)) = (w[0], w[1]);
            let (di, dj) = (a.abs_diff(c), b.abs_diff(d));
            match (di, dj) {
                (1, 0) | (0, 1) => true,
                (1, 1) => map.cell_free(a, d) && map.cell_free(c, b),
                _ => false,
            }
        })
}

/// Octile length of a cell path.
pub fn octile_length(cells: &[(usize, usize)]) -> f64 {
    cells
        .windows(2)
        .map(|w| {
            let (di, dj) = (w[0].0.abs_diff(w[1].0), w[0].1.abs_diff(w[1].1));
            if di + dj == 2 {
                std::f64::consts::SQRT_2
            } else {
                1.0
            }
        })
        .sum()
}

/// A `w x h` map of 1 m cells, each blocked with probability `density` (drawn from
/// `seed`), with the cells of `free` free.
pub fn random_map(w: usize, h: usize, density: f64, seed: u64, free: &[(usize, usize)]) -> GridMap {
    use rand::{Rng, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let zones = (0..w * h)
        .map(|_| {
            if rng.random_bool(density) {
                Zone::Forbidden
            } else {
                Zone::Free
            }
        })
        .collect();
    let mut map = GridMap::from_zones(w, h, 1.0, Point2::origin(), zones).unwrap();
    for &(i, j) in free {
        map.set_cell_zone(i, j, Zone::Free);
    }
    map
}

/// `map` with the cells of `flips` (taken modulo its size) turned from free to blocked or
/// back, but for those of `keep`; and the columns and rows of the cells changed (empty
/// when none).
pub fn flipped(
    map: &GridMap,
    flips: &[(usize, usize)],
    keep: &[(usize, usize)],
) -> (GridMap, Range<usize>, Range<usize>) {
    let mut changed = map.clone();
    let (w, h) = (map.width(), map.height());
    let (mut lo, mut hi) = ((w, h), (0, 0));
    for &(i, j) in flips {
        let (i, j) = (i % w, j % h);
        if keep.contains(&(i, j)) {
            continue;
        }
        let z = if changed.cell_zone(i, j) == Zone::Free {
            Zone::Forbidden
        } else {
            Zone::Free
        };
        changed.set_cell_zone(i, j, z);
        lo = (lo.0.min(i), lo.1.min(j));
        hi = (hi.0.max(i + 1), hi.1.max(j + 1));
    }
    (changed, lo.0..hi.0.max(lo.0), lo.1..hi.1.max(lo.1))
}
