//! Public-API tests of `sim`, one module per area.

mod kinematics;
mod laser;
mod explore;
mod navigation;
mod tracking;
