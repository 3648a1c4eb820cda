//! Every figure of the user guide (docs/guide) in one call: data from [`crate::data`], drawn with
//! [`crate::plot`] to `NAME.png` and `NAME.svg`, plus `figures.json` with the rapier-measured
//! points beside their references (what the tests check).

use crate::FigureError;
use crate::data::{example1, feeder, incline, popov, switch};
use crate::plot::{self, Bar, BarChart, Grid, LineChart, Mark, Series};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// How much to compute.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Size {
    /// CI size: coarse theory grids, two rapier points per curve, short runs.
    Quick,
    /// The user guide's figures.
    Full,
}

/// The data checked by the tests, written to `figures.json`.
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    /// Files written (PNG and SVG), in order.
    pub files: Vec<PathBuf>,
    /// Popov Fig. 4: rapier points beside theory, per waveform.
    pub popov: Vec<(String, Vec<popov::Measured>)>,
    /// Feeder amplitudes measured in rapier.
    pub feeder: Vec<feeder::FeederPoint>,
    /// Incline: per model, (label, ġ_t0, final displacement, largest |x|) after `incline_seconds`.
    pub incline: Vec<(String, Option<f64>, f64, f64)>,
    /// Incline run length (s).
    pub incline_seconds: f64,
    /// Example 1: per law, (label, core final x, rapier final x, rapier largest |x| in phase I).
    pub example1: Vec<(String, f64, f64, f64)>,
    /// Example 1 integration cost.
    pub timings: Vec<example1::Timing>,
}

/// Draws one figure into a directory under a name.
type Drawer<'a> = dyn Fn(&Path, &str) -> Result<[PathBuf; 2], FigureError> + 'a;

const SINGLE: (u32, u32) = (900, 600);
const DOUBLE: (u32, u32) = (1200, 1200);
const WIDE: (u32, u32) = (1400, 600);

/// The figure names (files `NAME.png`/`NAME.svg`) [`generate`] writes, in order.
pub const NAMES: [&str; 9] = [
    "switch_function",
    "sliding_curves",
    "example1",
    "example1_timings",
    "popov_fig4",
    "static_friction",
    "incline_creep",
    "feeder_speed",
    "elliptical_drive",
];

/// The pixel size of figure `name`.
pub fn pixel_size(name: &str) -> (u32, u32) {
    match name {
        "example1" => DOUBLE,
        "elliptical_drive" => WIDE,
        _ => SINGLE,
    }
}

/// Computes and draws every figure into `out` (created if missing); `progress` is told the
/// name of each figure before it is computed.
pub fn generate(out: &Path, size: Size, progress: &dyn Fn(&str)) -> Result<Summary, FigureError> {
    std::fs::create_dir_all(out).map_err(|e| FigureError::io(out, e))?;
    let quick = size == Size::Quick;
    let mut files = Vec::new();
    let mut save = |p: &Drawer, name: &str| -> Result<(), FigureError> {
        files.extend(p(out, name)?);
        Ok(())
    };

    progress("switch_function");
    let alpha = switch::switch_function(if quick { 101 } else { 401 });
    let chart = LineChart {
        title: "Switching function α(μ) (seed Eq. 5–7, Fig. 1 A)".into(),
        x_label: "|μ|".into(),
        y_label: "α".into(),
        series: curves(&alpha, Mark::Line),
        legend_lower: true,
        ..LineChart::default()
    };
    save(&|d, n| plot::save(&chart, d, n, SINGLE), "switch_function")?;

    progress("sliding_curves");
    let sliding = switch::sliding_curves(if quick { 101 } else { 401 })?;
    let chart = LineChart {
        title: "Sliding curves μ_ve(v) in use and Regul's μ(ġ)".into(),
        x_label: "slip speed (m/s)".into(),
        y_label: "μ".into(),
        series: curves(&sliding, Mark::Line),
        legend_lower: true,
        y_range: Some((0.0, 0.7)),
        ..LineChart::default()
    };
    save(&|d, n| plot::save(&chart, d, n, SINGLE), "sliding_curves")?;

    progress("example1");
    let v_regs: &[f64] = if quick {
        &[0.01, 0.001]
    } else {
        &[0.01, 0.001, 1e-4]
    };
    let ex = example1::compute(v_regs, if quick { 600 } else { 1500 })?;
    let panel = |traces: &[example1::Trace], force: bool, title: &str| LineChart {
        title: title.into(),
        x_label: "t (s)".into(),
        y_label: if force {
            "friction force on the block (N)"
        } else {
            "displacement (m)"
        }
        .into(),
        series: traces
            .iter()
            .enumerate()
            .map(|(i, tr)| Series {
                label: tr.label.clone(),
                x: tr.t.clone(),
                y: if force {
                    tr.friction.clone()
                } else {
                    tr.x.clone()
                },
                mark: if i == 0 { Mark::Dashed } else { Mark::Line },
                color: i,
            })
            .collect(),
        vlines: example1::PHASE_ENDS[..2].to_vec(),
        annotations: vec![(0.5, "I".into()), (1.5, "II".into()), (2.5, "III".into())],
        legend_lower: !force,
        ..LineChart::default()
    };
    // Phase I on a log scale: EP holds within g_ba like Phys, Regul creeps.
    let g_ba = example1::MU_BA / example1::C;
    let zoom = |traces: &[example1::Trace], title: &str| LineChart {
        title: title.into(),
        x_label: "t (s)".into(),
        y_label: "|displacement| (m), floor 1e-9".into(),
        series: traces
            .iter()
            .enumerate()
            .map(|(i, tr)| {
                let pts: Vec<(f64, f64)> =
                    tr.t.iter()
                        .zip(&tr.x)
                        .filter(|(t, _)| **t <= example1::PHASE_ENDS[0])
                        .map(|(&t, &x)| (t, x.abs().max(1e-9)))
                        .collect();
                Series::new(tr.label.clone(), &pts, Mark::Line, i)
            })
            .chain(std::iter::once(Series::new(
                "g_ba = μ_ba / c",
                &[(0.0, g_ba), (1.0, g_ba)],
                Mark::Dashed,
                7,
            )))
            .collect(),
        log_y: true,
        y_range: Some((1e-9, 0.1)),
        legend_lower: true,
        ..LineChart::default()
    };
    let grid = Grid {
        title: Some(
            "Seed Example 1 (Fig. 1 C): phases I stick, II stick-slip/slide, III slip-stick".into(),
        ),
        cols: 2,
        panels: vec![
            panel(&ex.core, false, "core ODE: displacement"),
            panel(&ex.rapier, false, "rapier (dt 1/240 s): displacement"),
            panel(&ex.core, true, "core ODE: friction force"),
            panel(&ex.rapier, true, "rapier: friction force"),
            zoom(&ex.core, "core ODE: phase I creep"),
            zoom(&ex.rapier, "rapier: phase I creep"),
        ],
    };
    save(&|d, n| plot::save(&grid, d, n, DOUBLE), "example1")?;
    let bars = |evals: bool| BarChart {
        title: if evals {
            "right-hand-side evaluations".into()
        } else {
            "integration time".into()
        },
        y_label: if evals {
            "evaluations"
        } else {
            "wall time (ms)"
        }
        .into(),
        bars: ex
            .timings
            .iter()
            .map(|t| Bar {
                label: format!("{} {}", short(&t.law), t.integrator),
                value: if evals {
                    t.evals.map(|e| e as f64)
                } else {
                    t.seconds.map(|s| s * 1e3)
                },
                color: match t.integrator.as_str() {
                    "RKF45" => 0,
                    "DoPri54" => 1,
                    _ => 2,
                },
            })
            .collect(),
        log_y: true,
        group_size: 3,
        groups: ex.timings.chunks(3).map(|c| short(&c[0].law)).collect(),
        legend: vec![
            ("RKF45 (explicit)".into(), 0),
            ("Dormand–Prince 5(4) (explicit)".into(), 1),
            ("ESDIRK 3(2) (implicit)".into(), 2),
        ],
    };
    let grid = Grid {
        title: Some("Example 1 integration cost (Fig. 1 D)".into()),
        cols: 1,
        panels: vec![bars(false), bars(true)],
    };
    save(&|d, n| plot::save(&grid, d, n, SINGLE), "example1_timings")?;

    progress("popov_fig4");
    let fig4 = popov::fig4(if quick { 60 } else { 280 }, quick)?;
    let mut series = Vec::new();
    for (i, c) in fig4.iter().enumerate() {
        series.push(Series {
            label: format!("{} theory", c.waveform),
            x: c.beta.clone(),
            y: c.theory.iter().map(|m| m / c.mu0).collect(),
            mark: Mark::Line,
            color: i,
        });
        series.push(Series {
            label: String::new(),
            x: c.measured.iter().map(|m| m.beta).collect(),
            y: c.measured.iter().map(|m| m.rapier / c.mu0).collect(),
            mark: Mark::Points,
            color: i,
        });
    }
    series.push(Series {
        label: "rapier (points)".into(),
        x: vec![],
        y: vec![],
        mark: Mark::Points,
        color: 7,
    });
    let chart = LineChart {
        title: "Popov Fig. 4: μ̄/μ0 = 1 − αΨ_w(β), α = 0.5; points: rapier".into(),
        x_label: "β = c v0 / (μ0 α f)".into(),
        y_label: "μ̄ / μ0".into(),
        series,
        legend_lower: true,
        ..LineChart::default()
    };
    save(&|d, n| plot::save(&chart, d, n, SINGLE), "popov_fig4")?;

    progress("static_friction");
    let st = popov::static_friction(if quick { 56 } else { 221 })?;
    let pts = |y: &[f64]| -> Vec<(f64, f64)> {
        st.ratio
            .iter()
            .zip(y)
            .map(|(&r, &m)| (r, m / st.mu0))
            .collect()
    };
    let chart = LineChart {
        title: "Static friction under oscillation, μ0 = 0.5 (Popov Eq. 4, 6, 8)".into(),
        x_label: "amplitude ratio A / F_z".into(),
        y_label: "μ_s / μ0".into(),
        series: vec![
            Series::new("normal (Eq. 4)", &pts(&st.normal), Mark::Line, 0),
            Series::new("tangential (Eq. 6)", &pts(&st.tangential), Mark::Line, 1),
            Series::new("transverse (Eq. 8)", &pts(&st.transverse), Mark::Line, 2),
        ],
        ..LineChart::default()
    };
    save(&|d, n| plot::save(&chart, d, n, SINGLE), "static_friction")?;

    progress("incline_creep");
    let seconds = if quick { 2.0 } else { 10.0 };
    let creep = incline::compute(seconds)?;
    let g_ba = incline::MU_BA / incline::C;
    let mut series: Vec<Series> = creep
        .iter()
        .enumerate()
        .map(|(i, c)| Series {
            label: c.label.clone(),
            x: c.t.clone(),
            y: c.x.iter().map(|x| x.abs().max(1e-9)).collect(),
            mark: Mark::Line,
            color: i,
        })
        .collect();
    series.push(Series {
        label: "g_ba = μ_ba / c".into(),
        x: vec![0.0, seconds],
        y: vec![g_ba, g_ba],
        mark: Mark::Dashed,
        color: 7,
    });
    let chart = LineChart {
        title: "Creep on an incline at tan θ = 0.95 μ_ba (rapier, 60 Hz)".into(),
        x_label: "t (s)".into(),
        y_label: "|displacement| (m), floor 1e-9".into(),
        series,
        log_y: true,
        legend_lower: true,
        y_range: Some((1e-9, 1.0)),
        ..LineChart::default()
    };
    save(&|d, n| plot::save(&chart, d, n, SINGLE), "incline_creep")?;

    progress("feeder_speed");
    let measured: Vec<f64> = if quick {
        vec![1.0e-3, 1.5e-3]
    } else {
        vec![0.8e-3, 1.0e-3, 1.2e-3, 1.4e-3, 1.6e-3, 1.8e-3, 2.0e-3]
    };
    let (line, points) = feeder::compute(if quick { 13 } else { 61 }, &measured)?;
    let gx = |p: &feeder::FeederPoint| p.amplitude * 1e3;
    let chart = LineChart {
        title: format!(
            "Vibratory feeder: f = {} Hz, throw angle {}°, μ = {}",
            feeder::FREQUENCY,
            feeder::ANGLE_DEG,
            feeder::MU
        ),
        x_label: "amplitude (mm)".into(),
        y_label: "transport speed (m/s)".into(),
        series: vec![
            Series::new(
                "rigid-body reference",
                &line
                    .iter()
                    .map(|p| (gx(p), p.reference))
                    .collect::<Vec<_>>(),
                Mark::Line,
                0,
            ),
            Series::new(
                "rapier plain, dt 1/30000 s",
                &points
                    .iter()
                    .filter_map(|p| Some((gx(p), p.plain_fine?)))
                    .collect::<Vec<_>>(),
                Mark::Points,
                1,
            ),
            Series::new(
                "rapier EP c = 1e5, dt 1/3000 s",
                &points
                    .iter()
                    .filter_map(|p| Some((gx(p), p.ep_coarse?)))
                    .collect::<Vec<_>>(),
                Mark::Crosses,
                3,
            ),
        ],
        legend_lower: true,
        ..LineChart::default()
    };
    save(&|d, n| plot::save(&chart, d, n, SINGLE), "feeder_speed")?;

    progress("elliptical_drive");
    // Popov's compliant contact under normal (α = 0.6) and tangential (1.5 slip lengths)
    // sine oscillation, the tangential one `shift` periods later: the static band, the
    // blocking force and the free drive velocity over the shift (stickslip_core::popov).
    let n = if quick { 9 } else { 41 };
    let shifts: Vec<f64> = (0..n).map(|i| -0.5 + i as f64 / (n - 1) as f64).collect();
    let drive = stickslip_core::popov::drive_curve(
        0.5,
        0.6,
        1.5,
        &stickslip_core::waveform::Waveform::Sine,
        1.0,
        &shifts,
    )?;
    let series = |f: &dyn Fn(&stickslip_core::popov::DrivePoint) -> f64| {
        drive
            .iter()
            .map(|p| (p.phase_shift, f(p)))
            .collect::<Vec<_>>()
    };
    let grid = Grid {
        title: Some(
            "Elliptical vibration (normal α = 0.6, tangential 1.5 slip lengths, sine, μ0 = 0.5)"
                .into(),
        ),
        cols: 2,
        panels: vec![
            LineChart {
                title: "friction over the mean normal force".into(),
                x_label: "phase shift of the tangential oscillation (periods)".into(),
                y_label: "μ̄".into(),
                series: vec![
                    Series::new("static band, upper", &series(&|p| p.upper), Mark::Line, 0),
                    Series::new("static band, lower", &series(&|p| p.lower), Mark::Line, 1),
                    Series::new(
                        "blocking force / F̄",
                        &series(&|p| p.blocking),
                        Mark::Dashed,
                        2,
                    ),
                    Series::new(
                        "μ̄ dragged at 1 speed scale",
                        &series(&|p| p.mu_eff),
                        Mark::Dashed,
                        3,
                    ),
                ],
                legend_lower: true,
                ..LineChart::default()
            },
            LineChart {
                title: "free drive velocity (no applied force)".into(),
                x_label: "phase shift of the tangential oscillation (periods)".into(),
                y_label: "velocity (slip lengths per period)".into(),
                series: vec![Series::new(
                    "theory",
                    &series(&|p| p.drive_velocity),
                    Mark::Line,
                    0,
                )],
                legend_lower: true,
                ..LineChart::default()
            },
        ],
    };
    save(&|d, n| plot::save(&grid, d, n, WIDE), "elliptical_drive")?;

    let summary = Summary {
        files,
        popov: fig4
            .iter()
            .map(|c| (c.waveform.clone(), c.measured.clone()))
            .collect(),
        feeder: points,
        incline: creep
            .iter()
            .map(|c| (c.label.clone(), c.v_reg, c.final_x(), c.max_abs_x()))
            .collect(),
        incline_seconds: seconds,
        example1: ex
            .core
            .iter()
            .zip(&ex.rapier)
            .map(|(c, r)| {
                (
                    c.label.clone(),
                    c.final_x(),
                    r.final_x(),
                    r.max_abs_x_until(example1::PHASE_ENDS[0]),
                )
            })
            .collect(),
        timings: ex.timings,
    };
    let json = out.join("figures.json");
    std::fs::write(&json, serde_json::to_string_pretty(&summary)?)
        .map_err(|e| FigureError::io(&json, e))?;
    Ok(summary)
}

fn curves(c: &[switch::Curve1], mark: Mark) -> Vec<Series> {
    c.iter()
        .enumerate()
        .map(|(i, c)| Series {
            label: c.label.clone(),
            x: c.x.clone(),
            y: c.y.clone(),
            mark,
            color: i,
        })
        .collect()
}

fn short(law: &str) -> String {
    law.replace("ġ_t0 = ", "")
}
