//! Writes the generated sections of the `docs/papers/` pages (the rendering is
//! [`harness::report::markdown`]).

use std::path::{Path, PathBuf};

use anyhow::Context as _;
use harness::Scenario;
use harness::report::{ExperimentResult, SeriesClaim, markdown};

/// Rewrites the generated section of every `docs/papers/NNN-*.md` page whose seed ran;
/// returns the pages written.
///
/// # Errors
///
/// A page that cannot be read or written, or that has a begin marker without an end.
pub fn update_docs(
    dir: &Path,
    results: &[(&Scenario, ExperimentResult)],
    series: &[SeriesClaim],
    quick: bool,
) -> anyhow::Result<Vec<PathBuf>> {
    let mut written = Vec::new();
    for page in crate::reproduce::files_ending_in(dir, "md")? {
        let Some(seed) = page
            .file_name()
            .and_then(|n| n.to_str())
            .and_then(|n| n.get(..3))
            .filter(|n| n.chars().all(|c| c.is_ascii_digit()))
        else {
            continue;
        };
        let seed = format!("{seed}_");
        if !results.iter().any(|(_, r)| r.seed_file.starts_with(&seed)) {
            continue;
        }
        let text = std::fs::read_to_string(&page)
            .with_context(|| format!("reading {}", page.display()))?;
        let section = markdown::page_section(results, series, &seed, quick);
        let Some(new) = markdown::splice_section(&text, &section) else {
            anyhow::bail!("{}: begin marker without an end", page.display());
        };
        std::fs::write(&page, new).with_context(|| format!("writing {}", page.display()))?;
        written.push(page);
    }
    Ok(written)
}
