//! Public-API tests of `sim`, one module per area.

mod building;
mod crowd;
mod explore;
mod kinematics;
mod laser;
mod map_crowd;
mod navigation;
mod orca;
mod profile;
mod reacting;
mod rollout;
mod social_force;
mod tracking;
