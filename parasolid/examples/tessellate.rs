//! Reads a Parasolid text transmit file and tessellates every body at a faceting tolerance,
//! reporting each body that does not close by name, each that is exactly one of the exact
//! engine's primitives, the triangle count and the time taken.
//!
//! `cargo run --release -p parasolid --example tessellate -- FILE.x_t [FT]` (FT defaults to
//! Adams' 300.0028).

use contact_core::FacetingTolerance;
use parasolid::{Body, Part, body_mesh};
use std::time::Instant;

fn main() -> std::process::ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(path) = args.first() else {
        eprintln!("usage: tessellate FILE.x_t [FT]");
        return std::process::ExitCode::FAILURE;
    };
    let ft = match args.get(1).map(|s| s.parse::<f64>()) {
        None => FacetingTolerance::DEFAULT,
        Some(Ok(v)) => match FacetingTolerance::new(v) {
            Ok(t) => t,
            Err(e) => {
                eprintln!("{e}");
                return std::process::ExitCode::FAILURE;
            }
        },
        Some(Err(e)) => {
            eprintln!("FT: {e}");
            return std::process::ExitCode::FAILURE;
        }
    };
    let start = Instant::now();
    let part = match Part::read(std::path::Path::new(path)) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("{e}");
            return std::process::ExitCode::FAILURE;
        }
    };
    let read = start.elapsed();
    let names = match part.body_names() {
        Ok(n) => n,
        Err(e) => {
            eprintln!("{e}");
            return std::process::ExitCode::FAILURE;
        }
    };
    let (mut triangles, mut failed) = (0usize, 0usize);
    let mut slowest = Vec::new();
    for n in &names {
        let began = Instant::now();
        let name = format!(
            "{}/{}",
            n.part.as_deref().unwrap_or("?"),
            n.element.as_deref().unwrap_or("?")
        );
        let body = Body::read(&part, n.index);
        if let Some(p) = body.as_ref().ok().and_then(parasolid::primitive::recognise) {
            println!("  {name}: exactly a primitive, {:?}", p.shape);
        }
        match body.and_then(|b| body_mesh(&part, &b, ft, &name)) {
            Ok(m) => {
                triangles += m.triangles().len();
                slowest.push((
                    began.elapsed().as_secs_f64(),
                    name.clone(),
                    m.triangles().len(),
                ));
            }
            Err(e) => {
                failed += 1;
                eprintln!("body {} ({name}): {e}", n.index);
            }
        }
    }
    let total = start.elapsed();
    slowest.sort_by(|a, b| b.0.total_cmp(&a.0));
    for (t, name, n) in slowest.iter().take(5) {
        println!("  {name}: {t:.3} s, {n} triangles");
    }
    println!(
        "{path}: schema {}, {} bodies ({failed} not closed), {triangles} triangles at FT {}; read {:.3} s, total {:.3} s",
        part.schema(),
        names.len(),
        ft.value(),
        read.as_secs_f64(),
        total.as_secs_f64()
    );
    if failed == 0 {
        std::process::ExitCode::SUCCESS
    } else {
        std::process::ExitCode::FAILURE
    }
}
