//! Criterion benches of hyplan's hot paths live in this package's `benches/` folder; the
//! library itself is empty.
