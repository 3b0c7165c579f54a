//! Tables: one writer for Markdown (reports) and CSV (data).

/// How a Markdown column is aligned.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Align {
    /// Text (`---`).
    #[default]
    Left,
    /// Numbers (`---:`).
    Right,
}

/// A table: headers and rows of cells, already formatted.
///
/// ```
/// use viz::{Align, Table};
/// let mut t = Table::new(["planner", "time (ms)"]).align([Align::Left, Align::Right]);
/// t.row(["rrt", "1.5"]);
/// assert_eq!(t.to_markdown(), "| planner | time (ms) |\n|---|---:|\n| rrt | 1.5 |\n");
/// assert_eq!(t.to_csv(), "planner,time (ms)\nrrt,1.5\n");
/// ```
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Table {
    headers: Vec<String>,
    align: Vec<Align>,
    rows: Vec<Vec<String>>,
}

impl Table {
    /// A table with these headers, every column left-aligned.
    #[must_use]
    pub fn new<S: Into<String>>(headers: impl IntoIterator<Item = S>) -> Self {
        let headers: Vec<String> = headers.into_iter().map(Into::into).collect();
        Self {
            align: vec![Align::Left; headers.len()],
            headers,
            rows: Vec::new(),
        }
    }

    /// With the columns aligned as given, in order (columns not named stay left).
    #[must_use]
    pub fn align(mut self, align: impl IntoIterator<Item = Align>) -> Self {
        for (slot, a) in self.align.iter_mut().zip(align) {
            *slot = a;
        }
        self
    }

    /// Adds a row of formatted cells.
    pub fn row<S: Into<String>>(&mut self, cells: impl IntoIterator<Item = S>) {
        self.rows.push(cells.into_iter().map(Into::into).collect());
    }

    /// The rows so far.
    #[must_use]
    pub fn rows(&self) -> &[Vec<String>] {
        &self.rows
    }

    /// The table in Markdown: `| a | b |` lines, the alignment line under the headers.
    #[must_use]
    pub fn to_markdown(&self) -> String {
        let line = |cells: &[String]| format!("| {} |\n", cells.join(" | "));
        let mut s = line(&self.headers);
        s.push('|');
        for a in &self.align {
            s.push_str(match a {
                Align::Left => "---|",
                Align::Right => "---:|",
            });
        }
        s.push('\n');
        for r in &self.rows {
            s.push_str(&line(r));
        }
        s
    }

    /// The table as CSV (RFC 4180): a header line, then the rows; a cell holding a comma,
    /// a quote or a line break is quoted.
    #[must_use]
    pub fn to_csv(&self) -> String {
        let line = |cells: &[String]| {
            let mut l = cells
                .iter()
                .map(|c| csv_cell(c))
                .collect::<Vec<_>>()
                .join(",");
            l.push('\n');
            l
        };
        let mut s = line(&self.headers);
        for r in &self.rows {
            s.push_str(&line(r));
        }
        s
    }
}

fn csv_cell(c: &str) -> String {
    if c.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", c.replace('"', "\"\""))
    } else {
        c.to_string()
    }
}
