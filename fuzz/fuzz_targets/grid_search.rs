//! Grid A* and Dijkstra agree on arbitrary small grids, and one `GridSearch` reused over
//! many queries answers like a fresh one.
//!
//! Input: width and height (1 to 32), the options (8- or 4-connected, corner cutting), then
//! one bit per cell (1 = blocked), then pairs of bytes choosing start and goal among the
//! free cells.
#![no_main]

use envmap::GridMap;
use hyplan_core::Zone;
use libfuzzer_sys::fuzz_target;
use search::{Connectivity, GridOptions, GridSearch, GridSearchError};

fuzz_target!(|data: &[u8]| {
    let [w, h, opts, rest @ ..] = data else {
        return;
    };
    let (w, h) = (usize::from(w % 32) + 1, usize::from(h % 32) + 1);
    let options = GridOptions {
        connectivity: if opts & 1 == 0 {
            Connectivity::Eight
        } else {
            Connectivity::Four
        },
        corner_cutting: opts & 2 != 0,
    };
    let cells = w * h;
    let (bits, picks) = rest.split_at(rest.len().min(cells.div_ceil(8)));
    let mut map = GridMap::filled(w, h, Zone::Free).expect("size");
    for k in 0..cells {
        if bits.get(k / 8).is_some_and(|b| (b >> (k % 8)) & 1 == 1) {
            map.set_cell_zone(k % w, k / w, Zone::Forbidden);
        }
    }
    let free: Vec<(usize, usize)> = (0..cells)
        .map(|k| (k % w, k / w))
        .filter(|&(i, j)| map.cell_free(i, j))
        .collect();
    if free.is_empty() {
        return;
    }
    let mut reused = GridSearch::new(&map, options).expect("small grid");
    for pair in picks.chunks_exact(2).take(300) {
        let a = free[usize::from(pair[0]) % free.len()];
        let b = free[usize::from(pair[1]) % free.len()];
        let mut fresh = GridSearch::new(&map, options).expect("small grid");
        let astar = reused.astar(a, b);
        let dijkstra = fresh.dijkstra(a, b);
        match (&astar, &dijkstra) {
            (Ok(p), Ok(d)) => {
                assert!((p.cost - d.cost).abs() < 1e-9, "{a:?} -> {b:?}");
                assert_eq!(p.cells.first(), Some(&a));
                assert_eq!(p.cells.last(), Some(&b));
                for s in p.cells.windows(2) {
                    let (di, dj) = (s[0].0.abs_diff(s[1].0), s[0].1.abs_diff(s[1].1));
                    assert!(di <= 1 && dj <= 1 && di + dj > 0);
                    assert!(map.cell_free(s[1].0, s[1].1));
                }
                let fresh_astar = fresh.astar(a, b).expect("found once");
                assert_eq!(fresh_astar.cells, p.cells);
            }
            (Err(GridSearchError::NoPath { .. }), Err(GridSearchError::NoPath { .. })) => {}
            _ => panic!("{a:?} -> {b:?}: {astar:?} vs {dijkstra:?}"),
        }
    }
});
