//! Prints the seed-004 replay section: `cargo run --release -p sim --example replay004`.
fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenarios/sim");
    let replay = sim::replay::seed004(&dir, 0)?;
    println!("{}", replay.markdown(None));
    Ok(())
}
