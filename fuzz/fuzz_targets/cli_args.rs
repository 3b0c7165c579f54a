//! `hyplan`'s argument parsing: any argument list (the input split at NUL bytes) is parsed
//! by the real `Cli` (clap derive, value parsers such as `--start X,Y` and `--smooth`)
//! without panicking; errors render without panicking either.
#![no_main]

use clap::Parser as _;
use libfuzzer_sys::fuzz_target;

// The binary's own modules, compiled into this target (hyplan has no library crate).
#[path = "../../crates/hyplan/src/main.rs"]
#[allow(dead_code, unused_imports, clippy::all)]
mod hyplan_main;
#[path = "../../crates/hyplan/src/planners.rs"]
#[allow(dead_code, unused_imports, clippy::all)]
mod planners;
#[allow(unused_imports)]
use hyplan_main::{EXIT_ERROR, EXIT_NO_PATH};

fuzz_target!(|data: &[u8]| {
    let args = std::iter::once("hyplan".to_string()).chain(
        data.split(|&b| b == 0)
            .map(|a| String::from_utf8_lossy(a).into_owned()),
    );
    match hyplan_main::Cli::try_parse_from(args) {
        Ok(_) => {}
        Err(e) => {
            let _ = e.render().to_string();
        }
    }
});
