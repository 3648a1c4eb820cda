//! The law of a pair: stickslip's materials where a collider has one, avian's `Friction`
//! (with its static coefficient) elsewhere, combined by avian's own rule.
//!
//! - Two plain avian sides combine with `Friction::combine` (avian's rule priority, Max >
//!   Multiply > Min > GeometricMean > Average). A static coefficient above the dynamic one
//!   gives the seed's exact switched law ("Phys"): held below μ_s without creep, sliding at
//!   μ_k. Otherwise the pair is avian's own Coulomb friction, and stickslip leaves it alone.
//! - A side with a stickslip material brings its law; a plain side brings "Phys" (or Coulomb
//!   at μ_k); the two laws combine with core's `Law::combine_or_coulomb` under avian's rule of
//!   the pair: a combination out of range (e.g. `Multiply` of two small coefficients) becomes
//!   plain Coulomb friction at the combined break-away coefficient, with a warning, as in
//!   stickslip-rapier.

use crate::rolling::RotationLaws;
use avian::prelude::{CoefficientCombine, Friction};
use bevy::platform::collections::HashMap;
use bevy::prelude::*;
use stickslip_bevy::StickSlipFriction;
use stickslip_core::FrictionMaterial;
use stickslip_core::law::{CombineRule, Coulomb, Law, Physical};
use stickslip_core::sliding_curve::Curve;

/// Combinations kept before the cache starts over (a bound, whatever the app spawns).
const MAX_COMBINATIONS: usize = 4096;

/// One side of a pair.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Side<'a> {
    /// A collider with `StickSlipFriction`: its entity (the cache's key) and material, and
    /// the combine rule of its avian `Friction`.
    Material(Entity, &'a FrictionMaterial, CoefficientCombine),
    /// A plain avian collider: its resolved `Friction`.
    Plain(Friction),
}

/// The cache key of a side.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum SideKey {
    Material(Entity),
    Plain(u32, u32),
}

impl Side<'_> {
    fn key(&self) -> SideKey {
        match self {
            Side::Material(e, _, _) => SideKey::Material(*e),
            Side::Plain(f) => SideKey::Plain(
                f.dynamic_coefficient.to_bits(),
                f.static_coefficient.to_bits(),
            ),
        }
    }

    fn rule(&self) -> CoefficientCombine {
        match self {
            Side::Material(_, _, r) => *r,
            Side::Plain(f) => f.combine_rule,
        }
    }

    fn law(&self) -> Law {
        match self {
            Side::Material(_, m, _) => m.law.clone(),
            Side::Plain(f) => plain_law(f.dynamic_coefficient as f64, f.static_coefficient as f64),
        }
    }
}

/// A plain avian friction as a law: "Phys" when it has static friction, else Coulomb.
fn plain_law(mu_k: f64, mu_s: f64) -> Law {
    if mu_s > mu_k
        && let Ok(curve) = Curve::constant(mu_k)
        && let Ok(law) = Physical::new(mu_s, curve)
    {
        return Law::Physical(law);
    }
    Law::Coulomb(Coulomb::clamped(mu_k))
}

/// avian's rule as core's.
fn rule(r: CoefficientCombine) -> CombineRule {
    match r {
        CoefficientCombine::Average => CombineRule::Average,
        CoefficientCombine::GeometricMean => CombineRule::GeometricMean,
        CoefficientCombine::Min => CombineRule::Min,
        CoefficientCombine::Multiply => CombineRule::Multiply,
        CoefficientCombine::Max => CombineRule::Max,
    }
}

/// The combined laws, by the two sides (canonical order).
#[derive(Resource, Default)]
pub(crate) struct PairLaws {
    combined: HashMap<(SideKey, SideKey), Option<Law>>,
    /// The rolling and spinning laws of pairs with a side that resists rotation.
    rotation: HashMap<(SideKey, SideKey), RotationLaws>,
}

impl PairLaws {
    /// Forgets every combination (a material changed or went).
    pub(crate) fn clear(&mut self) {
        self.combined.clear();
        self.rotation.clear();
    }

    /// The rolling and spinning laws of the pair `(a, b)`, or `None` when neither side's
    /// material resists rotation: a material's own, or both sides' combined by the pair's
    /// rule like the friction law (a plain side brings none).
    pub(crate) fn rotation<'a>(&mut self, a: Side<'a>, b: Side<'a>) -> Option<&RotationLaws> {
        let resists = |s: &Side| matches!(s, Side::Material(_, m, _) if m.resists_rotation());
        if !resists(&a) && !resists(&b) {
            return None;
        }
        let key = canonical(a.key(), b.key());
        if !self.rotation.contains_key(&key) && self.rotation.len() >= MAX_COMBINATIONS {
            self.rotation.clear();
        }
        Some(self.rotation.entry(key).or_insert_with(|| {
            let pair_rule = rule(a.rule().max(b.rule()));
            let material = |s: Side<'a>| match s {
                Side::Material(_, m, _) => Some(m),
                Side::Plain(_) => None,
            };
            let (m1, m2) = (material(a), material(b));
            let pick = |x: Option<&Law>, y: Option<&Law>| match (x, y) {
                (Some(x), Some(y)) if x == y => Some(x.clone()),
                (Some(x), Some(y)) => Some(x.combine_or_coulomb(y, pair_rule).0),
                (Some(x), None) | (None, Some(x)) => Some(x.clone()),
                (None, None) => None,
            };
            RotationLaws {
                rolling: pick(
                    m1.and_then(|m| m.rolling.as_ref()),
                    m2.and_then(|m| m.rolling.as_ref()),
                ),
                spinning: pick(
                    m1.and_then(|m| m.spinning.as_ref()),
                    m2.and_then(|m| m.spinning.as_ref()),
                ),
            }
        }))
    }

    /// The law of the pair `(a, b)`, or `None` when it is avian's own Coulomb friction.
    pub(crate) fn law(&mut self, a: Side, b: Side) -> Option<&Law> {
        let key = canonical(a.key(), b.key());
        if !self.combined.contains_key(&key) && self.combined.len() >= MAX_COMBINATIONS {
            self.combined.clear();
        }
        self.combined
            .entry(key)
            .or_insert_with(|| combine(a, b))
            .as_ref()
    }
}

/// The cache key of a pair: its side keys in canonical order.
fn canonical(ka: SideKey, kb: SideKey) -> (SideKey, SideKey) {
    if ka_order(ka) <= ka_order(kb) {
        (ka, kb)
    } else {
        (kb, ka)
    }
}

/// A total order of side keys (entities, then coefficient bits).
fn ka_order(k: SideKey) -> (u8, u64, u32) {
    match k {
        SideKey::Material(e) => (0, e.to_bits(), 0),
        SideKey::Plain(d, s) => (1, d as u64, s),
    }
}

fn combine(a: Side, b: Side) -> Option<Law> {
    if let (Side::Plain(fa), Side::Plain(fb)) = (a, b) {
        let c = fa.combine(fb);
        return (c.static_coefficient > c.dynamic_coefficient)
            .then(|| plain_law(c.dynamic_coefficient as f64, c.static_coefficient as f64));
    }
    let pair_rule = rule(a.rule().max(b.rule()));
    let (law, error) = a.law().combine_or_coulomb(&b.law(), pair_rule);
    if let Some(e) = error {
        // Once per combination: the cache keeps it.
        warn!(
            "stickslip: the materials of {a:?} and {b:?} do not combine by {pair_rule:?} \
             ({e}); the pair uses plain Coulomb friction"
        );
    }
    Some(law)
}

/// The side of a collider: its stickslip material (or the plugin's default for
/// `StickSlipFriction(None)`), else its avian friction (the collider's, its body's, or the
/// app's default).
pub(crate) fn side<'a>(
    entity: Entity,
    marked: Option<&'a StickSlipFriction>,
    friction: Option<&Friction>,
    body_friction: Option<&Friction>,
    default_friction: Friction,
    default_material: &'a FrictionMaterial,
) -> Side<'a> {
    let friction = friction
        .or(body_friction)
        .copied()
        .unwrap_or(default_friction);
    match marked {
        Some(StickSlipFriction(m)) => Side::Material(
            entity,
            m.as_ref().unwrap_or(default_material),
            friction.combine_rule,
        ),
        None => Side::Plain(friction),
    }
}
