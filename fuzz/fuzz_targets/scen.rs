//! The MovingAI `.scen` parser never panics, and what it returns is what the file says:
//! finite non-negative optima, line numbers after the version line, and cells that
//! `to_cell` flips into rows from the bottom exactly when they lie above the map's height.
#![no_main]

use libfuzzer_sys::fuzz_target;
use search::{ScenEntry, parse_scen};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(entries) = parse_scen(text, "fuzz.scen".as_ref()) {
        for e in &entries {
            assert!(e.optimal.is_finite() && e.optimal >= 0.0);
            assert!(e.line >= 2);
            assert!(!e.map_file_name().contains('/'));
            for (x, y) in [e.start, e.goal] {
                match ScenEntry::to_cell((x, y), e.height) {
                    Some((i, j)) => assert_eq!((i, j + y + 1), (x, e.height)),
                    None => assert!(y >= e.height),
                }
            }
        }
    }
});
