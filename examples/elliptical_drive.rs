use stickslip::rapier::VibrationMode;
use stickslip::rapier::scenes::VibratingPlate;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let mode = if args.get(1).map(|s| s.as_str()) == Some("avg") {
        VibrationMode::Averaged
    } else {
        VibrationMode::TimeResolved
    };
    for shift in [0.25, -0.25] {
        let p = VibratingPlate::elliptical(0.6, 0.75, shift, mode).unwrap();
        let t0 = std::time::Instant::now();
        let vd = p.theory_drive_velocity().unwrap();
        println!(
            "shift {shift}: theory v_d {vd:.5e} blocking {:.4} ({:?})",
            p.theory_blocking_force().unwrap(),
            t0.elapsed()
        );
        for fac in [0.0, 0.5, 0.9, 1.1, 2.0] {
            let v = fac * vd;
            let t0 = std::time::Instant::now();
            let m = p.drag(v, 6, 4).unwrap();
            println!(
                "  drag v {v:.4e}: rapier mu {:.4} theory {:.4} ({:?})",
                m.mu_eff,
                p.theory_mu(v).unwrap(),
                t0.elapsed()
            );
        }
        for (mass, warm) in [(100.0, 50), (100.0, 100), (30.0, 30), (30.0, 60), (10.0, 30)] {
            let mut p = p.clone();
            p.sled_mass = mass;
            let t0 = std::time::Instant::now();
            let m = p.run_free(0.0, warm, 10).unwrap();
            print!("mass {mass} ");
            println!("  free warm {warm}: v {:.4e} mu {:.4} ({:?})", m.velocity, m.mu_eff, t0.elapsed());
        }
    }
}
