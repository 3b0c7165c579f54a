//! Integration tests of the `hyplan` binary, one module per subcommand.

mod common;

mod bench;
mod bench_shard;
mod map;
mod plan;
mod scen;
mod sim;
