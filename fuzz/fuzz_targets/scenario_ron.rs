//! Any text as a RON scenario file: parsing and validation never panic, and scenarios
//! on a small in-memory grid (`map: Grid(..)`) build their world without panicking.
//!
//! Maps from files are not read (the fuzzer would name arbitrary paths), and grids are
//! kept to 65,536 cells with padding and bands of at most 16 cells, so that a slow input
//! means slow code, not a big map asked for.
#![no_main]

use std::path::Path;

use harness::{MapSpec, Scenario};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let path = Path::new("fuzz/scenario.ron");
    let Ok(scenario) = Scenario::parse(text, path) else {
        return;
    };
    if scenario.validate(path).is_err() {
        return;
    }
    if let MapSpec::Grid {
        width,
        height,
        safety_radius_cells,
        padding_cells,
        ..
    } = &scenario.map
        && width.saturating_mul(*height) <= 1 << 16
        && *padding_cells <= 16
        && safety_radius_cells.abs() <= 16.0
    {
        let _ = scenario.build_world(Path::new("/nonexistent"), path);
    }
});
