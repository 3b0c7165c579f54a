//! One module per subcommand.

pub mod map;
pub mod plan;
pub mod scen;
