//! Integration tests of the `hyplan` binary, one module per subcommand.

mod map;
mod plan;
mod scen;
mod sim;
