//! Writing sweep results: `NAME.csv`, `NAME.json` and one heat-map PNG per waveform (Popov)
//! or throw angle (feeder).

use super::feeder::{FeederPoint, FeederSweep};
use super::popov::{PopovPoint, PopovSweep};
use crate::FigureError;
use crate::plot::{self, HeatMap};
use serde::Serialize;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Heat-map size (px).
pub const HEATMAP_SIZE: (u32, u32) = (900, 600);

pub(crate) fn write(path: PathBuf, text: &str) -> Result<PathBuf, FigureError> {
    std::fs::write(&path, text).map_err(|e| FigureError::io(&path, e))?;
    Ok(path)
}

fn opt(v: Option<f64>) -> String {
    v.map_or(String::new(), |v| format!("{v:e}"))
}

#[derive(Serialize)]
struct Doc<'a, S, P> {
    sweep: &'a S,
    points: &'a [P],
}

/// The CSV table of Popov points (`popov.csv`), one row per point in the given order.
pub fn popov_csv(points: &[PopovPoint]) -> String {
    let mut csv = String::from("waveform,beta,alpha,theory,rapier,relative_error\n");
    for p in points {
        let err = p.rapier.map(|r| (r - p.theory) / p.theory);
        let _ = writeln!(
            csv,
            "{},{:e},{:e},{:e},{},{}",
            p.waveform,
            p.beta,
            p.alpha,
            p.theory,
            opt(p.rapier),
            opt(err)
        );
    }
    csv
}

/// The CSV table of feeder points (`feeder.csv`), one row per point in the given order.
pub fn feeder_csv(points: &[FeederPoint]) -> String {
    let mut csv = String::from(
        "amplitude_mm,frequency_hz,angle_deg,throw_number,rapier,reference,relative_error\n",
    );
    for p in points {
        let _ = writeln!(
            csv,
            "{:e},{:e},{:e},{:e},{:e},{:e},{:e}",
            p.amplitude_mm,
            p.frequency,
            p.angle_deg,
            p.throw_number,
            p.rapier,
            p.reference,
            (p.rapier - p.reference) / p.reference
        );
    }
    csv
}

/// Writes `popov.csv`, `popov.json` and `popov_WAVEFORM.png` (rapier's μ̄ over β × α, or
/// theory when rapier was not measured) into `dir`; returns the paths.
pub fn write_popov(
    dir: &Path,
    sweep: &PopovSweep,
    points: &[PopovPoint],
) -> Result<Vec<PathBuf>, FigureError> {
    std::fs::create_dir_all(dir).map_err(|e| FigureError::io(dir, e))?;
    let mut files = vec![
        write(dir.join("popov.csv"), &popov_csv(points))?,
        write(
            dir.join("popov.json"),
            &serde_json::to_string_pretty(&Doc { sweep, points })?,
        )?,
    ];
    let (xs, ys) = (sweep.beta.values(), sweep.alpha.values());
    for w in &sweep.waveforms {
        let values: Vec<f64> = points
            .iter()
            .filter(|p| p.waveform == w.name())
            .map(|p| p.rapier.unwrap_or(p.theory))
            .collect();
        let map = HeatMap {
            title: format!(
                "Popov μ̄ ({}), {}",
                w.name(),
                if sweep.rapier { "rapier" } else { "theory" }
            ),
            x_label: "β".into(),
            y_label: "α".into(),
            value_label: "mean μ".into(),
            xs: xs.clone(),
            ys: ys.clone(),
            values,
        };
        files.push(plot::save_png(
            &map,
            dir,
            &format!("popov_{}", w.name()),
            HEATMAP_SIZE,
        )?);
    }
    Ok(files)
}

/// Writes `feeder.csv`, `feeder.json` and `feeder_angle_DEG.png` (rapier's transport speed over
/// amplitude × frequency per throw angle) into `dir`; returns the paths.
pub fn write_feeder(
    dir: &Path,
    sweep: &FeederSweep,
    points: &[FeederPoint],
) -> Result<Vec<PathBuf>, FigureError> {
    std::fs::create_dir_all(dir).map_err(|e| FigureError::io(dir, e))?;
    let mut files = vec![
        write(dir.join("feeder.csv"), &feeder_csv(points))?,
        write(
            dir.join("feeder.json"),
            &serde_json::to_string_pretty(&Doc { sweep, points })?,
        )?,
    ];
    let (xs, ys) = (sweep.amplitude.values(), sweep.frequency.values());
    let per_angle = xs.len() * ys.len();
    for (k, g) in sweep.angle.values().into_iter().enumerate() {
        let values: Vec<f64> = points
            .iter()
            .skip(k * per_angle)
            .take(per_angle)
            .map(|p| p.rapier)
            .collect();
        let map = HeatMap {
            title: format!("Feeder transport speed in rapier, throw angle {g}°"),
            x_label: "amplitude (mm)".into(),
            y_label: "frequency (Hz)".into(),
            value_label: "speed (m/s)".into(),
            xs: xs.clone(),
            ys: ys.clone(),
            values,
        };
        files.push(plot::save_png(
            &map,
            dir,
            &format!("feeder_angle_{g}"),
            HEATMAP_SIZE,
        )?);
    }
    Ok(files)
}
