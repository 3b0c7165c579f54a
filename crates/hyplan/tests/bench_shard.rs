//! `hyplan bench --shard K/N` and `hyplan bench merge`: for 1, 2, 3 and 7 shards of one
//! experiment (4 planners x 2 maps x 3 queries x 50 runs), the merged outputs equal the
//! unsharded run's byte for byte outside the clocks; OMPL's script loads the merged logs
//! with every run; a shard killed half-way and run again merges to the same; missing,
//! duplicate and foreign shards are named and refused with exit 2.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use crate::common::{Scratch, assert_error, hyplan, repo_file, stderr};

const SCRATCH: Scratch = Scratch("hyplan_bench_shard");

const PLANNERS: [&str; 4] = [
    "rrt-connect",
    "rrt:max_iterations=150",
    "rrt-star:max_iterations=200,stop_at_first_solution=false",
    "astar",
];

/// Runs per planner and problem: 1 200 runs in all.
const RUNS: u32 = 50;

/// The experiment file (2 maps x 3 queries x 4 planners) with `seed`.
fn experiment(name: &str, seed: u64) -> String {
    let planners: Vec<String> = PLANNERS.iter().map(|p| format!("{p:?}")).collect();
    SCRATCH.file(
        &format!("{name}.ron"),
        format!(
            "(name: \"shard\", problems: [\
             (map: {:?}, queries: [((1.5, 11.5), (46.5, 46.5)), ((4.5, 4.5), (40.5, 30.5)), \
             ((45.5, 2.5), (2.5, 45.5))]), \
             (map: {:?}, queries: [((5.5, 5.5), (95.5, 95.5)), ((5.5, 95.5), (95.5, 5.5)), \
             ((50.5, 50.5), (4.5, 4.5))])], \
             planners: [{}], runs: {}, seed: {seed}, smooth: \"prune\", limits: Some((1.0, 1.0, 2.0)))",
            repo_file("data/movingai/arena.map"),
            repo_file("data/generated/rects100.map"),
            planners.join(", "),
            RUNS,
        ),
    )
}

fn fresh(name: &str) -> PathBuf {
    let p = SCRATCH.path(name);
    let _ = std::fs::remove_dir_all(&p);
    p
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn ok(o: &Output) {
    assert_eq!(o.status.code(), Some(0), "{}", stderr(o));
}

/// Runs the shards of `n` at the same time (one thread each), into `root/K`.
fn run_shards(file: &str, root: &Path, n: u32) -> Vec<PathBuf> {
    let dirs: Vec<PathBuf> = (0..n).map(|k| root.join(k.to_string())).collect();
    let children: Vec<_> = dirs
        .iter()
        .enumerate()
        .map(|(k, d)| {
            Command::new(env!("CARGO_BIN_EXE_hyplan"))
                .args(["bench", "--experiment", file, "--threads", "1"])
                .args(["--shard", &format!("{k}/{n}"), "--out", s(d)])
                .output()
        })
        .collect();
    for c in children {
        ok(&c.unwrap());
    }
    dirs
}

fn merge(dirs: &[PathBuf], out: &Path) -> Output {
    let mut args = vec!["bench", "merge"];
    args.extend(dirs.iter().map(|d| s(d)));
    args.extend(["--out", s(out)]);
    hyplan(&args)
}

/// The fields of one CSV line (RFC 4180 quotes).
fn csv_fields(line: &str) -> Vec<String> {
    let (mut out, mut cur, mut quoted) = (Vec::new(), String::new(), false);
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '"' if quoted && chars.peek() == Some(&'"') => {
                cur.push('"');
                chars.next();
            }
            '"' => quoted = !quoted,
            ',' if !quoted => out.push(std::mem::take(&mut cur)),
            c => cur.push(c),
        }
    }
    out.push(cur);
    out
}

/// `runs.csv` with the clock columns blanked.
fn csv_without_times(text: &str) -> String {
    let mut lines = text.lines();
    let header = csv_fields(lines.next().unwrap());
    let clocks: Vec<usize> = ["time_s", "planning_time_s", "cpu_time_s"]
        .iter()
        .map(|c| header.iter().position(|h| h == c).unwrap())
        .collect();
    let mut out = vec![header.join("|")];
    for line in lines {
        let mut f = csv_fields(line);
        for &c in &clocks {
            f[c] = "T".into();
        }
        out.push(f.join("|"));
    }
    out.join("\n")
}

/// `runs.json` without any clock: the runs', the summary's and comparisons' times, the
/// totals and the thread count.
fn json_without_times(text: &str) -> String {
    let mut j: serde_json::Value = serde_json::from_str(text).unwrap();
    let o = j.as_object_mut().unwrap();
    for key in [
        "wall_s",
        "sum_run_time_s",
        "sum_planning_time_s",
        "sum_planning_cpu_s",
        "command_cpu_s",
        "threads",
    ] {
        assert!(o.remove(key).is_some(), "{key}");
    }
    for run in o["runs"].as_array_mut().unwrap() {
        let r = run.as_object_mut().unwrap();
        for key in ["time_s", "cpu_time_s", "planning_time_s"] {
            assert!(r.remove(key).is_some(), "{key}");
        }
        for p in r
            .get_mut("progress")
            .and_then(|p| p.as_array_mut())
            .into_iter()
            .flatten()
        {
            p.as_object_mut().unwrap().remove("time_s");
        }
    }
    for row in o["summary"].as_array_mut().unwrap() {
        let row = row.as_object_mut().unwrap();
        for key in ["time_s", "planning_time_s"] {
            row.remove(key).unwrap();
        }
    }
    for c in o["comparisons"].as_array_mut().unwrap() {
        c.as_object_mut().unwrap().remove("time").unwrap();
    }
    serde_json::to_string_pretty(&j).unwrap()
}

/// `summary.md` without the time columns of both tables and the timing line.
fn markdown_without_times(text: &str) -> String {
    let mut out = Vec::new();
    // Columns of the times: (median, IQR, median with the smoothing) in the summary, (p,
    // delta, verdict) in the tests.
    let mut clocks: Vec<usize> = Vec::new();
    for line in text.lines() {
        if line.contains(" runs on ") && line.contains("Wall clock") {
            continue;
        }
        if !line.starts_with('|') {
            out.push(line.to_string());
            continue;
        }
        let mut cells: Vec<&str> = line.split('|').collect();
        if line.contains("time median") {
            // The planning call's median and IQR, and the median with the smoothing.
            clocks = (0..cells.len())
                .filter(|&c| cells[c].contains("(ms)"))
                .collect();
            assert_eq!(clocks.len(), 3, "{line}");
        } else if line.contains("time p") {
            clocks = vec![3, 4, 5];
        }
        for &c in &clocks {
            cells[c] = "T";
        }
        out.push(cells.join("|"));
    }
    out.join("\n")
}

/// An OMPL log without its clocks: host, start, total duration, the runs' `time`, `cpu
/// time` and `total time`, and the progress' `time`.
fn log_without_times(text: &str) -> String {
    let mut out = Vec::new();
    let mut lines = text.lines();
    while let Some(line) = lines.next() {
        if line.starts_with("Running on")
            || line.starts_with("Starting at")
            || line.ends_with("seconds spent to collect the data")
        {
            out.push("T".into());
            continue;
        }
        out.push(line.to_string());
        let words: Vec<&str> = line.split(' ').collect();
        let Some(k) = words[0].parse::<usize>().ok() else {
            continue;
        };
        let progress = line.ends_with("progress properties for each run");
        if !(progress || line.ends_with(" properties for each run")) {
            continue;
        }
        let names: Vec<String> = (0..k).map(|_| lines.next().unwrap().to_string()).collect();
        let clocks: Vec<usize> = names
            .iter()
            .enumerate()
            .filter(|(_, n)| {
                ["time REAL", "cpu time REAL", "total time REAL"].contains(&n.as_str())
            })
            .map(|(i, _)| i)
            .collect();
        out.extend(names);
        let count = lines.next().unwrap();
        out.push(count.to_string());
        let r: usize = count.split(' ').next().unwrap().parse().unwrap();
        for _ in 0..r {
            let run = lines.next().unwrap();
            let masked: Vec<String> = if progress {
                // Time points `v1,v2,v3,;`.
                run.split(';')
                    .map(|point| {
                        let mut v: Vec<&str> = point.split(',').collect();
                        for &c in &clocks {
                            if c < v.len() && !point.is_empty() {
                                v[c] = "T";
                            }
                        }
                        v.join(",")
                    })
                    .collect()
            } else {
                let mut v: Vec<&str> = run.split("; ").collect();
                for &c in &clocks {
                    v[c] = "T";
                }
                v.into_iter().map(String::from).collect()
            };
            out.push(masked.join(if progress { ";" } else { "; " }));
        }
    }
    out.join("\n")
}

/// Every output of a bench folder, the clocks masked, by file name.
fn outputs(dir: &Path) -> Vec<(String, String)> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| !n.ends_with(".db"))
        .collect();
    names.sort();
    names
        .into_iter()
        .filter(|n| !n.ends_with("-time.svg"))
        .map(|n| {
            let text = std::fs::read_to_string(dir.join(&n)).unwrap();
            let masked = match n.rsplit('.').next().unwrap() {
                "csv" => csv_without_times(&text),
                "json" => json_without_times(&text),
                "md" => markdown_without_times(&text),
                "log" => log_without_times(&text),
                // Length and success charts: byte for byte.
                _ => text,
            };
            (n, masked)
        })
        .collect()
}

fn assert_same(a: &Path, b: &Path) {
    let (x, y) = (outputs(a), outputs(b));
    let names = |v: &[(String, String)]| v.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>();
    assert_eq!(names(&x), names(&y), "{} vs {}", a.display(), b.display());
    for ((n, p), (_, q)) in x.iter().zip(&y) {
        assert!(
            p == q,
            "{n} differs outside the clocks: {} vs {}",
            a.display(),
            b.display()
        );
    }
}

#[test]
fn merged_shards_equal_the_unsharded_run() {
    let file = experiment("exp", 3);
    let whole = fresh("whole");
    ok(&hyplan(&[
        "bench",
        "--experiment",
        &file,
        "--out",
        s(&whole),
    ]));
    // 6 problems: log, charts; runs.csv, runs.json, summary.md.
    assert_eq!(std::fs::read_dir(&whole).unwrap().count(), 6 * 4 + 3);
    let total = 2 * 3 * 4 * RUNS as usize;
    for n in [1, 2, 3, 7] {
        let root = fresh(&format!("n{n}"));
        let dirs = run_shards(&file, &root, n);
        // Dealt round-robin: the shards' sizes differ by one at most.
        let sizes: Vec<usize> = dirs
            .iter()
            .map(|d| {
                std::fs::read_to_string(d.join("records.ron"))
                    .unwrap()
                    .lines()
                    .count()
                    - 1
            })
            .collect();
        assert_eq!(sizes.iter().sum::<usize>(), total, "{sizes:?}");
        assert!(
            sizes.iter().max().unwrap() - sizes.iter().min().unwrap() <= 1,
            "{sizes:?}"
        );
        // Given in any order.
        let mut shuffled = dirs.clone();
        shuffled.reverse();
        let merged = root.join("merged");
        ok(&merge(&shuffled, &merged));
        assert_same(&whole, &merged);
    }
    ompl_loads_every_run(&root_logs(&SCRATCH.path("n7/merged")), total);
}

fn root_logs(dir: &Path) -> Vec<PathBuf> {
    let mut logs: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "log"))
        .collect();
    logs.sort();
    logs
}

/// OMPL's `ompl_benchmark_statistics` loads the logs with every run. Skipped in one
/// printed line without the script, unless `HYPLAN_REQUIRE_TOOLS` is set.
fn ompl_loads_every_run(logs: &[PathBuf], runs: usize) {
    let script = "ompl_benchmark_statistics";
    if !crate::common::ompl_statistics_available() {
        return;
    }
    let db = fresh("merged.db");
    let o = Command::new(script)
        .arg("-d")
        .arg(&db)
        .args(logs)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let count = Command::new("python3")
        .arg("-c")
        .arg(
            "import sqlite3, sys\n\
             c = sqlite3.connect(sys.argv[1])\n\
             print(c.execute('SELECT COUNT(*) FROM runs').fetchone()[0], \
             c.execute('SELECT COUNT(*) FROM experiments').fetchone()[0])",
        )
        .arg(&db)
        .output()
        .unwrap();
    assert!(count.status.success(), "{}", stderr(&count));
    let text = String::from_utf8_lossy(&count.stdout).trim().to_string();
    assert_eq!(
        text,
        format!("{runs} {}", logs.len()),
        "runs, experiments in the database"
    );
}

#[test]
fn a_killed_shard_run_again_merges_to_the_same() {
    let file = experiment("kill", 5);
    let root = fresh("kill");
    let dirs = run_shards(&file, &root, 3);
    let first = root.join("first");
    ok(&merge(&dirs, &first));
    // Killed while writing its records: the manifest no longer matches them.
    let records = dirs[1].join("records.ron");
    let text = std::fs::read_to_string(&records).unwrap();
    std::fs::write(&records, &text[..text.len() / 2]).unwrap();
    let o = merge(&dirs, &root.join("refused"));
    assert_error(&o, &[s(&dirs[1]), "shard 1/3", "changed since"]);
    // Killed during its runs: a folder with no manifest (a re-run removes the old one
    // first), or with only a partial records file.
    std::fs::remove_file(dirs[1].join("shard.json")).unwrap();
    let o = merge(&dirs, &root.join("refused"));
    assert_error(&o, &[s(&dirs[1]), "no shard.json", "missing shard 1/3"]);
    assert!(
        !root.join("refused").exists(),
        "nothing is written when refused"
    );
    // Run again, it merges to the same outputs.
    let o = hyplan(&[
        "bench",
        "--experiment",
        &file,
        "--shard",
        "1/3",
        "--out",
        s(&dirs[1]),
    ]);
    ok(&o);
    let again = root.join("again");
    ok(&merge(&dirs, &again));
    assert_same(&first, &again);
}

#[test]
fn missing_duplicate_and_foreign_shards_are_refused() {
    let file = experiment("refuse", 7);
    let root = fresh("refuse");
    let dirs = run_shards(&file, &root, 3);
    // Missing.
    let o = merge(&[dirs[0].clone(), dirs[2].clone()], &root.join("out"));
    assert_error(&o, &["missing shard 1/3"]);
    // Duplicate: shard 2 copied to another folder.
    let copy = root.join("copy-of-2");
    std::fs::create_dir_all(&copy).unwrap();
    for f in ["shard.json", "records.ron"] {
        std::fs::copy(dirs[2].join(f), copy.join(f)).unwrap();
    }
    let mut with_copy = dirs.clone();
    with_copy.push(copy.clone());
    let o = merge(&with_copy, &root.join("out"));
    assert_error(&o, &[s(&copy), "shard 2/3", "duplicate"]);
    // Foreign: another seed, and the same experiment cut in two.
    let other = experiment("other", 8);
    let foreign = root.join("foreign");
    ok(&hyplan(&[
        "bench",
        "--experiment",
        &other,
        "--shard",
        "1/3",
        "--out",
        s(&foreign),
        "--runs",
        "1",
    ]));
    let halves = root.join("halves");
    ok(&hyplan(&[
        "bench",
        "--experiment",
        &file,
        "--shard",
        "1/2",
        "--out",
        s(&halves),
    ]));
    let o = merge(
        &[
            dirs[0].clone(),
            foreign.clone(),
            dirs[2].clone(),
            halves.clone(),
            dirs[1].clone(),
        ],
        &root.join("out"),
    );
    assert_error(
        &o,
        &[
            &format!("{} (shard 1/3): a shard of another experiment", s(&foreign)),
            &format!("{} (shard 1/2): a shard of another experiment", s(&halves)),
        ],
    );
    assert!(!root.join("out").exists());
    // The experiment file's `shard` runs the same shard as the flag.
    let in_file = SCRATCH.file(
        "refuse-in-file.ron",
        std::fs::read_to_string(&file).unwrap().replacen(
            "(name:",
            "(shard: Some(\"1/3\"), name:",
            1,
        ),
    );
    let from_file = root.join("from-file");
    ok(&hyplan(&[
        "bench",
        "--experiment",
        &in_file,
        "--out",
        s(&from_file),
    ]));
    // The same manifest but for the records' hash (their clocks differ).
    let manifest = |d: &Path| {
        let text = std::fs::read_to_string(d.join("shard.json")).unwrap();
        let mut m: serde_json::Value = serde_json::from_str(&text).unwrap();
        m.as_object_mut().unwrap().remove("records_sha256").unwrap();
        m
    };
    assert_eq!(manifest(&from_file), manifest(&dirs[1]));
    // A malformed shard is bad input, before any run.
    let o = hyplan(&[
        "bench",
        "--experiment",
        &file,
        "--shard",
        "3/3",
        "--out",
        s(&root.join("bad")),
    ]);
    assert_error(&o, &["3/3"]);
}
