//! The MCAP map reader never panics; an accepted grid holds width x height cells within
//! the limit, and reads as a three-zone map.
#![no_main]

use libfuzzer_sys::fuzz_target;

/// Small enough that the fuzzer cannot make the reader allocate much.
const MAX_CELLS: usize = 1 << 20;

fuzz_target!(|data: &[u8]| {
    let path = std::path::Path::new("fuzz/map.mcap");
    if let Ok(grid) = bag::occupancy_grid_from(data, path, "/map", MAX_CELLS) {
        let cells = grid.info.width as usize * grid.info.height as usize;
        assert!(cells >= 1 && cells <= MAX_CELLS);
        assert_eq!(grid.data.len(), cells);
        assert!(grid.info.resolution.is_finite() && grid.info.resolution > 0.0);
    }
});
