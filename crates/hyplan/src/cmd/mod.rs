//! One module per subcommand.

/// `println!` that returns the write error instead of panicking, so a closed pipe
/// (`hyplan ... | head`) ends the program quietly (see `main`).
macro_rules! outln {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        writeln!(std::io::stdout().lock(), $($arg)*)
    }};
}

pub mod map;
pub mod plan;
pub mod scen;
pub mod sim;
