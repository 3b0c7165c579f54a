//! Rewrites an MCAP file's messages with each chunk compression and prints the time and
//! size of each: what a run's bag would cost with another writer setting.
//!
//! `cargo run --release -p bag --example recompress -- run.mcap`

use std::io::Cursor;
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = std::env::args()
        .nth(1)
        .ok_or("usage: recompress FILE.mcap")?;
    let bytes = std::fs::read(&path)?;
    let messages = mcap::MessageStream::new(&bytes)?.collect::<Result<Vec<_>, _>>()?;
    let raw: usize = messages.iter().map(|m| m.data.len()).sum();
    println!("{path}: {} messages, {raw} bytes of CDR", messages.len());
    let settings = [
        ("none", None, 0),
        ("lz4", Some(mcap::Compression::Lz4), 0),
        ("zstd 1", Some(mcap::Compression::Zstd), 1),
        ("zstd 3", Some(mcap::Compression::Zstd), 3),
    ];
    for (name, compression, level) in settings {
        let mut best = f64::INFINITY;
        let mut size = 0;
        for _ in 0..5 {
            let start = Instant::now();
            let mut out = mcap::WriteOptions::new()
                .profile("ros2")
                .compression(compression)
                .compression_level(level)
                .compression_threads(0)
                .create(Cursor::new(Vec::new()))?;
            for m in &messages {
                out.write(m)?;
            }
            out.finish()?;
            best = best.min(start.elapsed().as_secs_f64());
            size = out.into_inner().into_inner().len();
        }
        println!(
            "{name:>7}: {:6.1} ms (best of 5), {size:>10} bytes",
            best * 1e3
        );
    }
    Ok(())
}
