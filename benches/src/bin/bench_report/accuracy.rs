//! The accuracy section: the scenes of `tests/rapier_*.rs` (built with
//! `stickslip::rapier::scenes`) run with plain rapier and with every law, each against its
//! analytic or reference value.

use crate::table::{Summary, num, pct, render, upct};
use rapier3d::prelude::*;
use std::fmt::Write as _;
use stickslip::core::law::{Coulomb, FrictionLaw, Law, Physical, Regularization, Regularized};
use stickslip::core::popov;
use stickslip::core::sliding_curve::Curve;
use stickslip::core::waveform::Waveform;
use stickslip::rapier::{
    Amplitude, FrictionMaterial, StickSlip, StickSlipConfig, VibrationDirection, VibrationMode,
    VibrationSource,
};
use stickslip_fixtures::{BoxOnGround, BoxScene, Conveyor};
use stickslip_theory::block::{Block, ForceProfile, Integrator, Tolerances, simulate};

const G: f64 = 9.81;

/// How a contact's friction is computed.
#[derive(Debug, Clone)]
enum Friction {
    /// Plain rapier with the colliders' coefficient.
    Plain(FrictionModel, f32),
    /// stickslip with a law.
    Law(Law),
}

impl Friction {
    fn label(&self) -> String {
        match self {
            Friction::Plain(FrictionModel::Coulomb, mu) => format!("plain rapier Coulomb, μ {mu}"),
            Friction::Plain(_, mu) => format!("plain rapier Simplified, μ {mu}"),
            Friction::Law(l) => match l {
                Law::ElastoPlastic(e) => format!(
                    "EP (c {}, μ_ba {}, μ_max {})",
                    num(e.c(), 2),
                    e.mu_ba(),
                    e.mu_max()
                ),
                Law::Physical(p) => format!(
                    "Phys (μ_ba {}, μ_ve {})",
                    p.mu_ba(),
                    l.sliding_coefficient(1.0)
                ),
                Law::Regularized(r) => format!(
                    "Regul (ġ_t0 {} m/s, μ_ve {})",
                    r.v_reg(),
                    l.sliding_coefficient(1.0)
                ),
                Law::Coulomb(c) => format!("Coulomb law via stickslip, μ {}", c.mu()),
            },
        }
    }
}

/// The laws of one test: plain rapier (both models), and EP, Phys, Regul, Coulomb via stickslip.
fn frictions(mu_ba: f64, mu_max: f64, mu_k: f64, c: f64, plain_mu: f64) -> Vec<Friction> {
    let curve = |m: f64| Curve::constant(m).expect("valid");
    vec![
        Friction::Plain(FrictionModel::Simplified, plain_mu as f32),
        Friction::Plain(FrictionModel::Coulomb, plain_mu as f32),
        Friction::Law(Law::elasto_plastic(c, mu_ba, mu_max, curve(mu_max)).expect("valid")),
        Friction::Law(Law::Physical(
            Physical::new(mu_ba, curve(mu_k)).expect("valid"),
        )),
        Friction::Law(Law::Regularized(
            Regularized::new(curve(mu_k), 0.01, Regularization::Linear).expect("valid"),
        )),
        Friction::Law(Law::Coulomb(Coulomb::new(plain_mu).expect("valid"))),
    ]
}

/// A box scene stepped with a friction choice and optional user hooks.
struct Rig<H: PhysicsHooks> {
    scene: BoxScene,
    modifier: Option<StickSlip<H>>,
    hooks: Option<H>,
}

impl<H: PhysicsHooks> Rig<H> {
    fn new(mut scene: BoxScene, friction: &Friction, hooks: H, config: StickSlipConfig) -> Self {
        match friction {
            Friction::Plain(model, mu) => {
                scene.world.integration_parameters.friction_model = *model;
                for h in [scene.ground, scene.box_collider] {
                    scene.world.colliders[h].set_friction(*mu);
                }
                let c = &mut scene.world.colliders[scene.ground];
                c.set_active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS);
                Rig {
                    scene,
                    modifier: None,
                    hooks: Some(hooks),
                }
            }
            Friction::Law(law) => {
                // The user's hook runs where the user flags it (as in the plain rig).
                let c = &mut scene.world.colliders[scene.ground];
                c.set_active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS);
                let mut m = StickSlip::with_hooks(FrictionMaterial::new(law.clone()), hooks)
                    .with_config(config)
                    .expect("valid config");
                m.attach(&mut scene.world.colliders, scene.ground, None);
                m.attach(&mut scene.world.colliders, scene.box_collider, None);
                Rig {
                    scene,
                    modifier: Some(m),
                    hooks: None,
                }
            }
        }
    }

    fn step(&mut self) {
        match (&mut self.modifier, &self.hooks) {
            (Some(m), _) => m.step(&mut self.scene.world),
            (None, Some(h)) => self.scene.world.step_with_events(h, &()),
            (None, None) => self.scene.world.step(),
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Incline.

const INC_MU_BA: f64 = 0.5;
const INC_MU_MAX: f64 = 0.55;
const INC_C: f64 = 1e4;

/// Displacement along the slope over `steps` after 60 settling steps.
fn incline_creep(friction: &Friction, theta: f64, steps: usize) -> f64 {
    let scene = BoxOnGround {
        incline: theta,
        ..BoxOnGround::default()
    }
    .build();
    let mut rig = Rig::new(scene, friction, (), StickSlipConfig::default());
    for _ in 0..60 {
        rig.step();
    }
    let x0 = rig.scene.x();
    for _ in 0..steps {
        rig.step();
    }
    rig.scene.x() - x0
}

/// Acceleration down a slope of tan θ = 0.7 over 1 s of sliding.
fn incline_acceleration(friction: &Friction, theta: f64) -> f64 {
    let scene = BoxOnGround {
        incline: theta,
        ..BoxOnGround::default()
    }
    .build();
    let mut rig = Rig::new(scene, friction, (), StickSlipConfig::default());
    for _ in 0..10 {
        rig.step();
    }
    let (x0, v0) = (rig.scene.x(), rig.scene.vx());
    let steps = 60;
    for _ in 0..steps {
        rig.step();
    }
    let t = steps as f64 / 60.0;
    2.0 * (rig.scene.x() - x0 - v0 * t) / (t * t)
}

fn incline(md: &mut String, summary: &mut Summary, smoke: bool) {
    let g_ba = INC_MU_BA / INC_C;
    let theta_stick = (0.95 * INC_MU_BA).atan();
    let theta_slide = 0.7f64.atan();
    let steps = if smoke { 30 } else { 600 };
    let _ = writeln!(
        md,
        "### Incline: creep at 0.95 of break-away, acceleration above it\n\n\
         `BoxOnGround` (0.5 m box, 125 kg, dt 1/60 s) on a slope. Creep: tan θ = 0.95 μ_ba \
         (μ_ba = 0.5; plain rapier with μ = 0.5), displacement over {} s after 1 s of settling; \
         the right answer is sticking, |x| ≤ g_ba = μ_ba/c = {} m (EP's elastic displacement). \
         Sliding: tan θ = 0.7, acceleration over 1 s against g (sin θ − μ_k cos θ) with μ_k \
         the law's sliding coefficient (EP, Phys and Regul slide with μ_ve = 0.55; plain rapier \
         and the Coulomb law with 0.5).\n",
        steps as f64 / 60.0,
        num(g_ba, 2)
    );
    let mut rows = Vec::new();
    for f in frictions(INC_MU_BA, INC_MU_MAX, INC_MU_MAX, INC_C, INC_MU_BA) {
        let creep = incline_creep(&f, theta_stick, steps);
        let mu_k = match &f {
            Friction::Plain(_, mu) => *mu as f64,
            Friction::Law(l) => l.sliding_coefficient(1.0),
        };
        let a = incline_acceleration(&f, theta_slide);
        let expect = G * (theta_slide.sin() - mu_k * theta_slide.cos());
        let a_err = (a - expect) / expect;
        let sticks = creep.abs() <= g_ba;
        if let Friction::Law(Law::ElastoPlastic(_)) = f {
            summary.add(
                "incline creep at 0.95 break-away, EP (10 s)",
                "≤ g_ba = 5e-5 m",
                format!("{} m", num(creep, 3)),
                sticks,
            );
            summary.add(
                "incline sliding acceleration, EP",
                "within 2 %",
                pct(a_err),
                a_err.abs() <= 0.02,
            );
        }
        rows.push(vec![
            f.label(),
            num(creep, 3),
            num(creep / g_ba, 3),
            if sticks {
                "sticks".into()
            } else {
                "creeps/slides".into()
            },
            num(a, 4),
            num(expect, 4),
            pct(a_err),
        ]);
    }
    md.push_str(&render(
        &[
            "friction",
            "creep (m)",
            "creep / g_ba",
            "at 0.95 break-away",
            "a (m/s²)",
            "analytic a",
            "a error",
        ],
        &rows,
    ));
}

// ---------------------------------------------------------------------------------------------
// Belt.

const BELT_K: f64 = 100.0;
const BELT_V: f64 = 0.1;

/// Mean stick-slip period on the belt (stick onsets when |v − v_b| < 1 mm/s).
fn belt_period(friction: &Friction, seconds: f64) -> Option<f64> {
    let dt = 1.0 / 480.0;
    let scene = BoxOnGround {
        half: 0.1,
        mass: 1.0,
        dt: dt as f32,
        rotations: false,
        ..BoxOnGround::default()
    }
    .build();
    let conveyor = Conveyor {
        belt: scene.ground,
        velocity: Vector::new(BELT_V as f32, 0.0, 0.0),
    };
    let mut rig = Rig::new(scene, friction, conveyor, StickSlipConfig::default());
    let mut onsets = Vec::new();
    let mut was_stuck = false;
    for k in 0..(seconds / dt) as usize {
        let x = rig.scene.x();
        rig.scene
            .set_force(Vector::new((-BELT_K * x) as f32, 0.0, 0.0));
        rig.step();
        let stuck = (rig.scene.vx() - BELT_V).abs() < 1e-3;
        if stuck && !was_stuck && k > 0 {
            onsets.push((k + 1) as f64 * dt);
        }
        was_stuck = stuck;
    }
    let periods: Vec<f64> = onsets.windows(2).skip(2).map(|w| w[1] - w[0]).collect();
    (periods.len() >= 3).then(|| periods.iter().sum::<f64>() / periods.len() as f64)
}

fn analytic_period(mu_s: f64, mu_k: f64) -> f64 {
    let omega = BELT_K.sqrt(); // m = 1 kg
    let delta = (mu_s - mu_k) * G / BELT_K;
    if delta > 0.0 {
        2.0 * delta / BELT_V
            + (std::f64::consts::PI + 2.0 * (BELT_V / (omega * delta)).atan()) / omega
    } else {
        2.0 * std::f64::consts::PI / omega
    }
}

fn belt(md: &mut String, summary: &mut Summary, smoke: bool) {
    let seconds = if smoke { 1.0 } else { 8.0 };
    let _ = writeln!(
        md,
        "### Belt: stick-slip period\n\n\
         A 1 kg box (rotations locked) on a belt moving at {BELT_V} m/s (the user's conveyor \
         hook, wrapped by stickslip), tied to a wall by k = {BELT_K} N/m, dt 1/480 s, {seconds} s. \
         Analytic period T = 2Δ/v_b + (π + 2 atan(v_b/(ωΔ)))/ω with Δ = (μ_s − μ_k) N/k; plain \
         friction (Δ = 0) gives the limit 2π/ω = {} s. Phys has μ_ba = 0.5 over μ_k = 0.3 \
         (Δ > 0); EP slides with no less than μ_ba (see the law's docs), so it runs with \
         μ_ba = 0.29, μ_max = μ_ve = 0.3 and is compared with the Δ = 0 limit, as are Regul \
         (μ_ve = 0.3) and plain friction 0.3. “—”: fewer than 3 stick onsets (no stick-slip).\n",
        num(analytic_period(0.3, 0.3), 4)
    );
    let curve = |m: f64| Curve::constant(m).expect("valid");
    let cases: Vec<(Friction, f64, f64)> = vec![
        (Friction::Plain(FrictionModel::Simplified, 0.3), 0.3, 0.3),
        (Friction::Plain(FrictionModel::Coulomb, 0.3), 0.3, 0.3),
        (
            Friction::Law(Law::elasto_plastic(1e4, 0.29, 0.3, curve(0.3)).expect("valid")),
            0.3,
            0.3,
        ),
        (
            Friction::Law(Law::Physical(
                Physical::new(0.5, curve(0.3)).expect("valid"),
            )),
            0.5,
            0.3,
        ),
        (
            Friction::Law(Law::Physical(
                Physical::new(0.3, curve(0.3)).expect("valid"),
            )),
            0.3,
            0.3,
        ),
        (
            Friction::Law(Law::Regularized(
                Regularized::new(curve(0.3), 0.01, Regularization::Linear).expect("valid"),
            )),
            0.3,
            0.3,
        ),
        (
            Friction::Law(Law::Coulomb(Coulomb::new(0.3).expect("valid"))),
            0.3,
            0.3,
        ),
    ];
    let mut rows = Vec::new();
    for (f, mu_s, mu_k) in cases {
        let t = analytic_period(mu_s, mu_k);
        let got = belt_period(&f, seconds);
        let err = got.map(|g| (g - t) / t);
        if let (Friction::Law(Law::Physical(p)), Some(e)) = (&f, err)
            && p.mu_ba() > 0.4
        {
            summary.add(
                "belt stick-slip period, Phys (μ_s 0.5 > μ_k 0.3)",
                "within 2 %",
                pct(e),
                e.abs() <= 0.02,
            );
        }
        if let Friction::Law(Law::ElastoPlastic(_)) = f {
            summary.info(
                "belt period, EP (Δ = 0 limit)",
                "2π/ω",
                err.map_or("no stick-slip".into(), pct),
            );
        }
        rows.push(vec![
            f.label(),
            format!("{mu_s} / {mu_k}"),
            num(t, 4),
            got.map_or("—".into(), |g| num(g, 4)),
            err.map_or("—".into(), pct),
        ]);
    }
    md.push_str(&render(
        &[
            "friction",
            "μ_s / μ_k",
            "analytic T (s)",
            "measured T (s)",
            "error",
        ],
        &rows,
    ));
}

// ---------------------------------------------------------------------------------------------
// Popov.

const P_MU0: f64 = 0.5;
const P_C: f64 = 1e4;
const P_ALPHA: f64 = 0.5;
const P_F: f64 = 5.0;
const P_FN: f64 = 9.81;

#[derive(Debug, Clone, Copy, PartialEq)]
enum Drive {
    RealLoad,
    Source(VibrationMode),
}

/// μ̄ of a massive sled dragged at v0 (β) over the plate, measured from the sled's momentum:
/// its x velocity is reset to v0 before each step, so the friction is m Δv / dt.
fn popov_mu_bar(
    friction: &Friction,
    waveform: &Waveform,
    beta: f64,
    drive: Drive,
    smoke: bool,
) -> f64 {
    let spp = match drive {
        Drive::Source(VibrationMode::Averaged) => 40,
        _ => 400,
    };
    let spp = if smoke { spp / 10 } else { spp };
    let dt = 1.0 / (P_F * spp as f64);
    let scene = BoxOnGround {
        half: 0.1,
        mass: 1000.0,
        gravity: 0.0,
        dt: dt as f32,
        rotations: false,
        ..BoxOnGround::default()
    }
    .build();
    let config = StickSlipConfig::default();
    let mut rig = Rig::new(scene, friction, (), config);
    if let (Drive::Source(mode), Some(m)) = (drive, rig.modifier.as_mut()) {
        let src = VibrationSource::new(
            VibrationDirection::Normal,
            Amplitude::Ratio(P_ALPHA),
            P_F,
            waveform.clone(),
            0.0,
            mode,
        )
        .expect("valid source");
        m.set_vibration(rig.scene.ground, src);
    }
    let mass = rig.scene.world.bodies[rig.scene.body].mass() as f64;
    let v0 = beta * P_MU0 * P_ALPHA * P_F / P_C;
    let settle = match drive {
        Drive::RealLoad => (5.0 * P_F).ceil() as usize,
        Drive::Source(_) => 0,
    };
    let warm = ((1.0 - P_ALPHA) / (P_ALPHA * beta)).ceil() as usize + 3 + settle;
    let warm = if smoke { 1 } else { warm };
    let periods = warm + if smoke { 1 } else { 4 };
    let (mut sum_fx, mut sum_fz) = (0.0, 0.0);
    for k in 0..(periods * spp) {
        let t_mid = (k as f64 + 0.5) * dt;
        let w = waveform.value(P_F * t_mid);
        let load = match drive {
            Drive::RealLoad => P_FN * (1.0 + P_ALPHA * w),
            Drive::Source(_) => P_FN,
        };
        {
            let b = &mut rig.scene.world.bodies[rig.scene.body];
            b.set_linvel(Vector::new(v0 as f32, b.linvel().y, 0.0), true);
        }
        rig.scene.set_force(Vector::new(0.0, -(load as f32), 0.0));
        rig.step();
        if k >= warm * spp {
            let dv = rig.scene.vx() - v0 as f32 as f64;
            sum_fx += -mass * dv / dt;
            sum_fz += load;
        }
    }
    sum_fx / sum_fz
}

fn beta_grid(w: &Waveform) -> Vec<f64> {
    let bc = w.beta_c();
    if bc.is_finite() {
        vec![0.25 * bc, 0.6 * bc, 0.9 * bc, 1.5 * bc]
    } else {
        vec![0.5, 2.0, 5.0, 12.0]
    }
}

fn popov_section(md: &mut String, summary: &mut Summary, smoke: bool) {
    let waves = [
        ("sine", Waveform::Sine),
        ("sawtooth-right", Waveform::SawtoothRight),
        ("sawtooth-left", Waveform::SawtoothLeft),
        ("square", Waveform::Square),
    ];
    let waves = if smoke { &waves[..1] } else { &waves[..] };
    let _ = writeln!(
        md,
        "### Popov: μ̄ under normal vibration across β\n\n\
         A 1000 kg sled pressed on a plate with F̄ = {P_FN} N, its normal force modulated as \
         F̄ (1 + α w(f t)) (α = {P_ALPHA}, f = {P_F} Hz), dragged at v0 = β μ0 α f / c. Theory \
         (core): μ̄ = μ0 (1 − α Ψ_w(β)) with μ0 = {P_MU0} and the contact stiffness of the EP law \
         (k_t = c F̄, c = {}). The friction is measured from the sled's momentum (m Δv/dt each \
         step), the same way for every law. β grid: 0.25, 0.6, 0.9 and 1.5 β_c (β_c = ∞: 0.5, 2, \
         5, 12). EP runs in the seed's sharp limit (μ_ba = μ_max = μ0); the rigid laws have no \
         tangential compliance, so they cannot show the vibration's friction reduction and stay \
         near μ0.\n",
        num(P_C, 2)
    );
    let curve = |m: f64| Curve::constant(m).expect("valid");
    let ep = Law::elasto_plastic(P_C, P_MU0, P_MU0, curve(P_MU0)).expect("valid");
    let mut cases: Vec<(Friction, Drive, &str)> = frictions(P_MU0, P_MU0, P_MU0, P_C, P_MU0)
        .into_iter()
        .map(|f| {
            let f = match f {
                Friction::Law(Law::ElastoPlastic(_)) => Friction::Law(ep.clone()),
                other => other,
            };
            (f, Drive::RealLoad, "real oscillating load")
        })
        .collect();
    cases.push((
        Friction::Law(ep.clone()),
        Drive::Source(VibrationMode::TimeResolved),
        "time-resolved source",
    ));
    cases.push((
        Friction::Law(ep),
        Drive::Source(VibrationMode::Averaged),
        "averaged source",
    ));
    let mut rows = Vec::new();
    let mut detail = Vec::new();
    for (f, drive, drive_name) in &cases {
        let (mut worst, mut sum, mut n) = (0.0f64, 0.0, 0);
        for (wname, w) in waves {
            let grid = beta_grid(w);
            let grid = if smoke { &grid[..1] } else { &grid[..] };
            for &beta in grid {
                let theory = P_MU0 * (1.0 - P_ALPHA * popov::psi(w, beta).unwrap_or(f64::NAN));
                let got = popov_mu_bar(f, w, beta, *drive, smoke);
                let err = (got - theory) / theory;
                worst = worst.max(err.abs());
                sum += err.abs();
                n += 1;
                if matches!(f, Friction::Law(Law::ElastoPlastic(_))) {
                    detail.push(vec![
                        drive_name.to_string(),
                        wname.to_string(),
                        num(beta, 3),
                        num(theory, 4),
                        num(got, 4),
                        pct(err),
                    ]);
                }
            }
        }
        if matches!(f, Friction::Law(Law::ElastoPlastic(_))) {
            summary.add(
                format!("Popov μ̄ across β, EP, {drive_name}"),
                "within 3 %",
                format!("worst {}", upct(worst)),
                worst <= 0.03,
            );
        }
        rows.push(vec![
            f.label(),
            drive_name.to_string(),
            upct(sum / n.max(1) as f64),
            upct(worst),
        ]);
    }
    md.push_str(&render(
        &["friction", "modulation", "mean |error|", "worst |error|"],
        &rows,
    ));
    md.push_str("<details><summary>EP, every waveform and β</summary>\n\n");
    md.push_str(&render(
        &[
            "modulation",
            "waveform",
            "β",
            "theory μ̄",
            "rapier μ̄",
            "error",
        ],
        &detail,
    ));
    md.push_str("</details>\n\n");
}

// ---------------------------------------------------------------------------------------------
// Example 1.

fn example1(md: &mut String, summary: &mut Summary, smoke: bool) {
    let (mu_ba, mu_max, c) = (0.3, 0.32, 1e4);
    let mass = 1.0;
    let profile = ForceProfile::example1(mu_ba * mass * G, 0.95, 1.5).expect("valid");
    let curve = Curve::constant(mu_max).expect("valid");
    let reference = simulate(
        &Block::new(
            mass,
            G,
            Law::Physical(Physical::new(mu_ba, curve.clone()).expect("valid")),
        )
        .expect("valid"),
        &profile,
        Integrator::Explicit,
        Tolerances::default(),
        &[1.0, 3.0],
    )
    .expect("reference run");
    let x_ref = reference.final_displacement();
    let dt = 1.0 / 240.0;
    let end = if smoke { 0.2 } else { 3.0 };
    let g_ba = mu_ba / c;
    let _ = writeln!(
        md,
        "### The seed's Example 1 in rapier\n\n\
         A 1 kg box (rotations locked) under the force F(t) of Example 1 (0.95 F_ba held, then \
         1.5 F_ba, then released), dt 1/240 s. Reference: the core's exact switched model (Phys, \
         μ_ba = {mu_ba}, μ_ve = {mu_max}) integrated by RKF45 at rtol 1e-8: final displacement \
         {} m; it breaks away at max(μ_ba, μ_ve(0+)) = {mu_max}, so plain friction uses μ = \
         {mu_max}. Phase I should not move more than g_ba = μ_ba/c = {} m.\n",
        num(x_ref, 6),
        num(g_ba, 2)
    );
    let mut rows = Vec::new();
    for f in frictions(mu_ba, mu_max, mu_max, c, mu_max) {
        let scene = BoxOnGround {
            half: 0.1,
            mass: mass as f32,
            dt: dt as f32,
            rotations: false,
            ..BoxOnGround::default()
        }
        .build();
        let mut rig = Rig::new(scene, &f, (), StickSlipConfig::default());
        for _ in 0..(0.1 / dt).ceil() as usize {
            rig.step();
        }
        let x0 = rig.scene.x();
        let mut phase1: f64 = 0.0;
        for k in 0..(end / dt).round() as usize {
            let t_mid = (k as f64 + 0.5) * dt;
            rig.scene
                .set_force(Vector::new(profile.value(t_mid) as f32, 0.0, 0.0));
            rig.step();
            if (k + 1) as f64 * dt <= 1.0 {
                phase1 = phase1.max((rig.scene.x() - x0).abs());
            }
        }
        let x_end = rig.scene.x() - x0;
        let err = (x_end - x_ref) / x_ref;
        if let Friction::Law(Law::ElastoPlastic(_)) = f {
            summary.add(
                "Example 1 in rapier, EP final displacement vs Phys ODE",
                "within 2 %",
                pct(err),
                err.abs() <= 0.02,
            );
        }
        rows.push(vec![
            f.label(),
            num(phase1, 3),
            if phase1 <= g_ba { "yes" } else { "no" }.into(),
            num(x_end, 6),
            pct(err),
            num(rig.scene.vx(), 2),
        ]);
    }
    md.push_str(&render(
        &[
            "friction",
            "phase I max |x| (m)",
            "≤ g_ba",
            "final x (m)",
            "error vs reference",
            "final v (m/s)",
        ],
        &rows,
    ));
}

pub fn section(md: &mut String, summary: &mut Summary, smoke: bool) {
    let _ = writeln!(
        md,
        "## Accuracy in rapier worlds\n\n\
         The scenes of `tests/rapier_*.rs` (built with `stickslip::rapier::scenes`), run with \
         plain rapier friction (both friction models) and with stickslip's laws: EP (the \
         point of stickslip), Phys (exact switched), Regul (ġ_t0 = 0.01 m/s, linear ramp) and \
         plain Coulomb through stickslip.\n"
    );
    incline(md, summary, smoke);
    belt(md, summary, smoke);
    popov_section(md, summary, smoke);
    example1(md, summary, smoke);
}
