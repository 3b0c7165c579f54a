//! A paper's claim checked on our runs, and the report table of several.

use crate::Table;

/// One claim of a paper, checked on our runs: what the paper says, where, what we
/// measured, and whether it held.
///
/// ```
/// use viz::{Claim, claims_markdown};
/// let c = Claim {
///     text: "the person makes the trip longer".into(),
///     paper: "38.8 s vs 36.4 s".into(),
///     ours: "38.1 s vs 36.0 s".into(),
///     held: true,
/// };
/// assert_eq!(c.verdict(), "held");
/// assert!(claims_markdown(&[c]).ends_with("| 38.1 s vs 36.0 s | held |\n"));
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Claim {
    /// What the paper says.
    pub text: String,
    /// The paper's figure, table or number.
    pub paper: String,
    /// Ours.
    pub ours: String,
    /// Whether it held.
    pub held: bool,
}

impl Claim {
    /// `held` or `not held`.
    #[must_use]
    pub const fn verdict(&self) -> &'static str {
        if self.held { "held" } else { "not held" }
    }
}

/// The claims as a Markdown table (claim, paper, ours, held).
#[must_use]
pub fn claims_markdown(claims: &[Claim]) -> String {
    let mut t = Table::new(["claim", "paper", "ours", "held"]);
    for c in claims {
        t.row([c.text.as_str(), &c.paper, &c.ours, c.verdict()]);
    }
    t.to_markdown()
}

/// How many of the claims held.
#[must_use]
pub fn claims_held(claims: &[Claim]) -> usize {
    claims.iter().filter(|c| c.held).count()
}
