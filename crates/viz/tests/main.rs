//! viz's integration tests, one binary.

// Scenes drawn to SVG and PNG; animations.
mod scene;
// The plan figure: one zone layer under one set of marks, the same in PNG and SVG.
mod plan;
// Tables and claims, output exact.
mod table;
