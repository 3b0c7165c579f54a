//! One module per subcommand.

/// `println!` that returns the write error instead of panicking, so a closed pipe
/// (`hyplan ... | head`) ends the program quietly (see `main`).
macro_rules! outln {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        writeln!(std::io::stdout().lock(), $($arg)*)
    }};
}

/// `envmap::load_map`, with the flag that raises the memory limit named when a map is
/// refused for its size.
pub fn load_map(
    path: &std::path::Path,
    opts: &envmap::LoadOptions,
) -> anyhow::Result<envmap::LoadedMap> {
    envmap::load_map(path, opts).map_err(|e| match e {
        envmap::MapError::TooLarge { width, height, .. } => anyhow::anyhow!(
            "{e}; raise the limit with --max-cells {}",
            width.saturating_mul(height)
        ),
        e => e.into(),
    })
}

pub mod bench;
pub mod explore;
pub mod map;
pub mod plan;
pub mod planners;
pub mod scen;
pub mod sim;
