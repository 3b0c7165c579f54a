//! Public-API tests of `sim`, one module per area.

mod explore;
mod kinematics;
mod laser;
mod navigation;
mod tracking;
