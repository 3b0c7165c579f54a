//! Shared fixtures.

use std::path::PathBuf;

use envmap::GridMap;

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
