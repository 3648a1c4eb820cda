use stickslip::core::block::{Integrator, Tolerances};
use stickslip::core::chain::*;
use stickslip::core::law::*;
use stickslip::core::sliding_curve::Curve;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let t_end: f64 = args.get(1).map(|s| s.parse().unwrap()).unwrap_or(0.1);
    let links: usize = args.get(2).map(|s| s.parse().unwrap()).unwrap_or(250);
    let p = ChainParams {
        links,
        ..ChainParams::timing_drive()
    };
    let mu = 0.1;
    let curve = Curve::constant(mu).unwrap();
    let out_dt = 1.0 / (p.drive_frequency * 10.0);
    let tol = |r: f64| Tolerances {
        rtol: r,
        atol: r * 1e-3,
        max_steps: 50_000_000,
    };
    let reg = |v: f64| {
        Chain::new(
            p,
            ChainLaw::Regularized(
                Regularized::new(curve.clone(), v, Regularization::Linear).unwrap(),
            ),
        )
        .unwrap()
    };
    let ep = |c: f64| {
        Chain::new(
            p,
            ChainLaw::ElastoPlastic(ElastoPlastic::new(c, 0.9 * mu, mu, curve.clone()).unwrap()),
        )
        .unwrap()
    };
    let refv: f64 = std::env::var("REFV")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1e-4);
    let reference = simulate(&reg(refv), Integrator::Explicit, tol(1e-9), t_end, out_dt).unwrap();
    println!(
        "ref: {:.3}s steps {} W {:.6}",
        reference.stats.seconds,
        reference.stats.accepted_steps,
        reference.final_work()
    );
    let rms = reference.rms_displacement();
    let r2 = simulate(
        &reg(refv * 10.0),
        Integrator::Explicit,
        tol(1e-9),
        t_end,
        out_dt,
    )
    .unwrap();
    println!("ref x10 err {:?}", r2.error_against(&reference));
    for i in [0, 10, 25, 50, 100, 150, 200, 249] {
        if i < rms.len() {
            print!("x{i}:{:.2e} ", rms[i]);
        }
    }
    println!();
    if std::env::var("IMPL").is_ok() {
        for r in [1e-3, 1e-4] {
            let run = simulate(&reg(0.01), Integrator::Implicit, tol(r), t_end, out_dt).unwrap();
            println!(
                "impl rtol {r:e} regul 0.01: {:.3}s steps {} rej {} evals {} err {:?}",
                run.stats.seconds,
                run.stats.accepted_steps,
                run.stats.rejected_steps,
                run.stats.function_evals,
                run.error_against(&reference)
            );
            let run = simulate(&ep(1e5), Integrator::Implicit, tol(r), t_end, out_dt).unwrap();
            println!(
                "impl rtol {r:e} ep 1e5: {:.3}s steps {} rej {} evals {} err {:?}",
                run.stats.seconds,
                run.stats.accepted_steps,
                run.stats.rejected_steps,
                run.stats.function_evals,
                run.error_against(&reference)
            );
        }
        return;
    }
    if std::env::var("SKIP").is_ok() {
        return;
    }
    let epref = simulate(&ep(1e7), Integrator::Explicit, tol(1e-9), t_end, out_dt).unwrap();
    println!(
        "EP c=1e7 tight: {:.3}s steps {} err {:?}",
        epref.stats.seconds,
        epref.stats.accepted_steps,
        epref.error_against(&reference)
    );
    for integ in [Integrator::Explicit, Integrator::DormandPrince] {
        for r in [1e-3, 1e-4, 1e-5, 1e-6] {
            for v in [0.1, 0.01, 0.001] {
                match simulate(&reg(v), integ, tol(r), t_end, out_dt) {
                    Ok(run) => println!(
                        "{integ:?} rtol {r:e} regul {v}: {:.3}s steps {} rej {} err {:?}",
                        run.stats.seconds,
                        run.stats.accepted_steps,
                        run.stats.rejected_steps,
                        run.error_against(&reference)
                    ),
                    Err(e) => println!(
                        "{integ:?} rtol {r:e} regul {v}: failed {}",
                        &format!("{e}")[..60.min(format!("{e}").len())]
                    ),
                }
            }
            for c in [1e4, 1e5, 1e6] {
                match simulate(&ep(c), integ, tol(r), t_end, out_dt) {
                    Ok(run) => println!(
                        "{integ:?} rtol {r:e} ep c={c:e}: {:.3}s steps {} rej {} err {:?}",
                        run.stats.seconds,
                        run.stats.accepted_steps,
                        run.stats.rejected_steps,
                        run.error_against(&reference)
                    ),
                    Err(e) => println!(
                        "{integ:?} rtol {r:e} ep c={c:e}: failed {}",
                        &format!("{e}")[..60.min(format!("{e}").len())]
                    ),
                }
            }
        }
    }
}
