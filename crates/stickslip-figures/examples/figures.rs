//! The README's figures without the CLI's other dependencies (the same as
//! `stickslip figures`): `cargo run --release -p stickslip-figures --example figures --
//! [OUT_DIR] [--quick]`.

fn main() -> Result<(), stickslip_figures::FigureError> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let quick = args.iter().any(|a| a == "--quick");
    let out = args
        .iter()
        .find(|a| !a.starts_with("--"))
        .map_or("docs/figures", |s| s.as_str());
    let size = if quick {
        stickslip_figures::Size::Quick
    } else {
        stickslip_figures::Size::Full
    };
    let started = std::time::Instant::now();
    let summary = stickslip_figures::generate(std::path::Path::new(out), size, &|name| {
        eprintln!("[{:6.1} s] {name}", started.elapsed().as_secs_f64());
    })?;
    for f in summary.files {
        println!("{}", f.display());
    }
    eprintln!("done in {:.1} s", started.elapsed().as_secs_f64());
    Ok(())
}
