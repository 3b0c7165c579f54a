//! Integration tests of the `hyplan` binary, one module per subcommand.

mod bench;
mod map;
mod plan;
mod scen;
mod sim;
