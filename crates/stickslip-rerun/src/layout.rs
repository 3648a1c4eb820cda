//! The viewer layout sent with every recording (a rerun blueprint), so that a recording opens
//! usefully without any manual setup: the 3D scene (bodies, contact points coloured by regime,
//! friction arrows) large on the left; on the right, contacts by regime, the world's forces
//! and power, and the per-body series (speed, displacement, forces) below each other.

use crate::paths;
use rerun::blueprint::{Blueprint, Horizontal, Spatial3DView, TimeSeriesView, Vertical};

/// The layout (see the [module docs](self)).
pub fn blueprint() -> Blueprint {
    let regimes: Vec<String> = paths::REGIME_SERIES
        .iter()
        .map(|s| format!("/{}/{s}", paths::WORLD_SERIES))
        .collect();
    let totals: Vec<String> = paths::TOTAL_SERIES
        .iter()
        .map(|s| format!("/{}/{s}", paths::WORLD_SERIES))
        .collect();
    Blueprint::new(
        Horizontal::new([
            Spatial3DView::new("scene")
                .with_origin(format!("/{}", paths::WORLD))
                .into(),
            Vertical::new([
                TimeSeriesView::new("contacts by regime")
                    .with_contents(regimes)
                    .into(),
                TimeSeriesView::new("forces, power, energy")
                    .with_contents(totals)
                    .into(),
                TimeSeriesView::new("bodies")
                    .with_origin("/series/bodies")
                    .into(),
            ])
            .into(),
        ])
        .with_column_shares([2.0, 1.0]),
    )
}
