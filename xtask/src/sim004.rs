//! The seed-004 section of `cargo xtask reproduce`: the `sim` crate's replay of the
//! paper's three navigation scenarios (`scenarios/sim/`), figures and report section.

use std::path::Path;

/// Runs the replay, writes its figures under `figures/004-navigation/`, and returns the
/// report section and (claims held, claims).
pub fn section(root: &Path, figures: &Path) -> anyhow::Result<(String, usize, usize)> {
    let replay = sim::replay::seed004(&root.join("scenarios/sim"), 0)?;
    replay.write_figures(&figures.join("004-navigation"))?;
    let held = replay.claims.iter().filter(|c| c.held).count();
    eprintln!(
        "004-navigation: 3 runs in {:.2} s, claims held {held}/{}",
        replay.elapsed_s,
        replay.claims.len()
    );
    Ok((
        replay.markdown(Some("figures/004-navigation")),
        held,
        replay.claims.len(),
    ))
}
