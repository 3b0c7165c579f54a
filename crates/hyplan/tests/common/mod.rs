//! What the subcommand tests share: running the built binary, reading its output, scratch
//! files and the repository's test data.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs the built `hyplan` binary with `args` and waits for it.
pub fn hyplan(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_hyplan"))
        .args(args)
        .output()
        .expect("the hyplan binary runs")
}

pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Command-line words written as one line, split at white space:
/// `flags("--runs 3 --json")`. Paths go in as words of their own.
pub fn flags(line: &str) -> Vec<&str> {
    line.split_whitespace().collect()
}

/// Stdout read as the one JSON value it must be.
pub fn json(o: &Output) -> serde_json::Value {
    serde_json::from_slice(&o.stdout).expect("stdout is one JSON value")
}

/// Exit code `code` and a stderr containing every needle.
pub fn assert_exit(o: &Output, code: i32, needles: &[&str]) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(code), "stderr: {err}");
    for n in needles {
        assert!(err.contains(n), "stderr should mention {n:?}: {err}");
    }
}

/// Exit code 2, one `error: ` line containing every needle, no panic.
pub fn assert_error(o: &Output, needles: &[&str]) {
    assert_exit(o, 2, needles);
    let err = stderr(o);
    assert!(err.starts_with("error: "), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}

/// A file of the repository (path from its root); a missing one fails the test with its
/// path.
pub fn repo_file(rel: &str) -> String {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(rel);
    assert!(p.exists(), "test data missing: {}", p.display());
    p.display().to_string()
}

/// One test module's folder in the target's scratch space. Tests run in parallel: each
/// module writes in its own folder, each test under its own names.
pub struct Scratch(pub &'static str);

impl Scratch {
    /// `name` (may hold folders) in this folder; its parent folders are made.
    pub fn path(&self, name: &str) -> PathBuf {
        let p = Path::new(env!("CARGO_TARGET_TMPDIR"))
            .join(self.0)
            .join(name);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        p
    }

    /// Writes `contents` to `name`; returns its path as text.
    pub fn file(&self, name: &str, contents: impl AsRef<[u8]>) -> String {
        let p = self.path(name);
        std::fs::write(&p, contents).unwrap();
        p.display().to_string()
    }
}

/// The cells of a ROS map's grey levels as Nav2's trinary rule reads them (negate 0,
/// thresholds 0.65 and 0.196): `[free, occupied, unknown]`.
pub fn nav2_counts(grey: &[u8]) -> [usize; 3] {
    let mut n = [0; 3];
    for &g in grey {
        let occ = (255.0 - f64::from(g)) / 255.0;
        n[if occ > 0.65 {
            1
        } else if occ < 0.196 {
            0
        } else {
            2
        }] += 1;
    }
    n
}

/// Whether OMPL's `ompl_benchmark_statistics` (package ompl-demos) runs here. Without it
/// a test prints one SKIPPED line and returns, unless `HYPLAN_REQUIRE_TOOLS` is set (as
/// `.ci/run` sets it): then it fails.
pub fn ompl_statistics_available() -> bool {
    let script = "ompl_benchmark_statistics";
    if std::process::Command::new(script)
        .arg("--help")
        .output()
        .is_ok_and(|o| o.status.success())
    {
        return true;
    }
    assert!(
        std::env::var_os("HYPLAN_REQUIRE_TOOLS").is_none(),
        "`{script}` not found (apt-get install ompl-demos) and HYPLAN_REQUIRE_TOOLS is set"
    );
    eprintln!("SKIPPED: `{script}` not found (apt-get install ompl-demos)");
    false
}
