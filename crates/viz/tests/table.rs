use viz::{Align, Claim, Table, claims_held, claims_markdown};

#[test]
fn markdown_is_exact() {
    let mut t = Table::new(["planner", "success", "CPU (ms)"]).align([
        Align::Left,
        Align::Right,
        Align::Right,
    ]);
    t.row(["rrt", "100%", "1.50 ± 0.20"]);
    t.row(["astar", "100%", "-"]);
    assert_eq!(
        t.to_markdown(),
        "| planner | success | CPU (ms) |\n|---|---:|---:|\n| rrt | 100% | 1.50 ± 0.20 |\n| astar | 100% | - |\n"
    );
}

#[test]
fn csv_quotes_only_what_needs_it() {
    let mut t = Table::new(["label", "value"]);
    t.row(["rrt:step=2,goal_bias=0.1", "1"]);
    t.row([r#"say "hi""#, "2"]);
    t.row(["plain", ""]);
    assert_eq!(
        t.to_csv(),
        "label,value\n\"rrt:step=2,goal_bias=0.1\",1\n\"say \"\"hi\"\"\",2\nplain,\n"
    );
}

#[test]
fn claims_table_is_exact() {
    let claims = [
        Claim {
            text: "a".into(),
            paper: "Fig. 1".into(),
            ours: "x".into(),
            held: true,
        },
        Claim {
            text: "b".into(),
            paper: "Fig. 2".into(),
            ours: "y".into(),
            held: false,
        },
    ];
    assert_eq!(
        claims_markdown(&claims),
        "| claim | paper | ours | held |\n|---|---|---|---|\n| a | Fig. 1 | x | held |\n| b | Fig. 2 | y | not held |\n"
    );
    assert_eq!(claims_held(&claims), 1);
}
