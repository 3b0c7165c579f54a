//! Public-API tests of `postproc`, as one binary.

mod errors;
mod grid;
mod pchip_props;
mod prune_props;
mod scipy;
mod smooth_props;
mod spline_props;
mod timing_props;
