//! Which law a contact uses: only pairs with an attached collider are stickslip's; their law
//! is the per-pair override if there is one, else the two sides' materials combined like
//! rapier combines friction coefficients (see `stickslip_core::law::CombineRule`):
//!
//! - an attached collider brings its material (the modifier's default if it was attached
//!   without one) and its rapier `friction_combine_rule`;
//! - an unattached collider brings its rapier `friction` as a plain Coulomb material and its
//!   rapier `friction_combine_rule`;
//! - the rule is the higher of the two in rapier's order (GeometricMean > ClampedSum > Max >
//!   Multiply > Min > Average), as rapier does.
//!
//! Combined laws are computed once per combination (material ids or plain coefficient, and
//! rule) and cached; the cache holds at most [`MAX_COMBINATIONS`] (a world that changes a
//! plain collider's `friction` every step only refills it). A combination whose coefficients
//! leave the valid range (e.g. `Multiply` of two tiny coefficients) becomes plain Coulomb at
//! the combined break-away coefficient, clamped into range, with a one-time warning.

use crate::collider_map::{ColliderBits, ColliderMap};
use crate::fast_hash::HashMap;
use crate::warnings::{Warned, Warning};
use rapier::prelude::*;
use stickslip_core::FrictionMaterial;
use stickslip_core::law::{CombineRule, Coulomb, Law};

/// Most combined laws the cache keeps before it starts over.
#[doc(hidden)]
pub const MAX_COMBINATIONS: usize = 4096;

/// One side of a pair, as far as its law is concerned.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub(crate) enum Side {
    /// An attached collider: its material's id in the palette (0: the default material).
    Material(u32),
    /// An unattached collider: its rapier friction coefficient (f32 bits).
    Plain(u32),
}

/// A combination: both sides in a canonical order, and the rule.
pub(crate) type CombineKey = (Side, Side, CombineRule);

/// stickslip's rule for rapier's.
#[doc(hidden)]
pub fn combine_rule(rule: CoefficientCombineRule) -> CombineRule {
    match rule {
        CoefficientCombineRule::Average => CombineRule::Average,
        CoefficientCombineRule::Min => CombineRule::Min,
        CoefficientCombineRule::Multiply => CombineRule::Multiply,
        CoefficientCombineRule::Max => CombineRule::Max,
        CoefficientCombineRule::ClampedSum => CombineRule::ClampedSum,
        CoefficientCombineRule::GeometricMean => CombineRule::GeometricMean,
    }
}

/// Materials by id; id 0 is the default material.
#[derive(Debug, Clone)]
pub(crate) struct Palette(Vec<FrictionMaterial>);

impl Palette {
    pub fn new(default: FrictionMaterial) -> Self {
        Palette(vec![default])
    }

    pub fn get(&self, id: u32) -> &FrictionMaterial {
        self.0.get(id as usize).unwrap_or(&self.0[0])
    }

    pub fn default_material(&self) -> &FrictionMaterial {
        &self.0[0]
    }

    /// The id of `material`, added if new (the palette holds each distinct material once).
    pub fn id(&mut self, material: FrictionMaterial) -> u32 {
        match self.0.iter().position(|m| *m == material) {
            Some(i) => i as u32,
            None => {
                self.0.push(material);
                (self.0.len() - 1) as u32
            }
        }
    }
}

/// The pair key of a per-pair override: the two handles in a canonical order.
pub(crate) fn pair_key(a: ColliderHandle, b: ColliderHandle) -> (ColliderHandle, ColliderHandle) {
    let raw = |h: ColliderHandle| h.0.into_raw_parts();
    if raw(a) <= raw(b) { (a, b) } else { (b, a) }
}

fn plain_law(mu: f64) -> Law {
    Law::Coulomb(Coulomb::clamped(mu))
}

/// Every material in use and how a pair's law is found: the attached colliders' materials,
/// per-pair overrides and the cache of combined laws.
#[derive(Debug)]
pub(crate) struct PairLaws {
    /// Every material in use, by id (0: the default).
    palette: Palette,
    /// The material id of colliders attached with a material of their own.
    materials: ColliderMap<u32>,
    /// Per-pair overrides, by [`pair_key`].
    pairs: PairMaterials,
    /// Laws of combined materials.
    combined: Combined,
}

impl PairLaws {
    /// Heap bytes held (capacity included): palette, own materials, overrides, combined laws.
    pub fn heap_bytes(&self) -> usize {
        crate::heap::vec_bytes(&self.palette.0)
            + self.materials.heap_bytes()
            + crate::heap::map_bytes(&self.pairs)
            + self.combined.heap_bytes()
    }

    /// Laws whose attached colliders default to `default`.
    pub fn new(default: FrictionMaterial) -> Self {
        PairLaws {
            palette: Palette::new(default),
            materials: ColliderMap::default(),
            pairs: PairMaterials::default(),
            combined: Combined::default(),
        }
    }

    pub fn default_material(&self) -> &FrictionMaterial {
        self.palette.default_material()
    }

    /// The material a collider was given (`None`: the default).
    pub fn material(&self, collider: ColliderHandle) -> Option<&FrictionMaterial> {
        self.materials.get(collider).map(|&id| self.palette.get(id))
    }

    /// Every collider's own material.
    pub fn materials(&self) -> impl Iterator<Item = (ColliderHandle, &FrictionMaterial)> {
        self.materials
            .iter()
            .map(|(h, &id)| (h, self.palette.get(id)))
    }

    pub fn set_material(&mut self, collider: ColliderHandle, material: FrictionMaterial) {
        let id = self.palette.id(material);
        self.materials.insert(collider, id);
    }

    /// The collider goes back to the default material.
    pub fn clear_material(&mut self, collider: ColliderHandle) {
        self.materials.remove(collider);
    }

    pub fn set_pair(&mut self, a: ColliderHandle, b: ColliderHandle, material: FrictionMaterial) {
        self.pairs.insert(pair_key(a, b), material);
    }

    pub fn remove_pair(
        &mut self,
        a: ColliderHandle,
        b: ColliderHandle,
    ) -> Option<FrictionMaterial> {
        self.pairs.remove(&pair_key(a, b))
    }

    pub fn pair(&self, a: ColliderHandle, b: ColliderHandle) -> Option<&FrictionMaterial> {
        self.pairs.get(&pair_key(a, b))
    }

    /// Every pair's own material.
    pub fn pairs(
        &self,
    ) -> impl Iterator<Item = ((ColliderHandle, ColliderHandle), &FrictionMaterial)> {
        self.pairs.iter().map(|(&k, m)| (k, m))
    }

    /// Drops the collider's own material and every pair material it is part of.
    pub fn remove_collider(&mut self, collider: ColliderHandle) {
        self.materials.remove(collider);
        self.pairs
            .retain(|&(a, b), _| a != collider && b != collider);
    }

    fn side(
        &self,
        attached: &ColliderBits,
        colliders: &ColliderSet,
        h: ColliderHandle,
    ) -> (Side, CombineRule) {
        let c = colliders.get(h);
        let rule = c.map_or(CombineRule::Average, |c| {
            combine_rule(c.friction_combine_rule())
        });
        if attached.contains(h) {
            (
                Side::Material(self.materials.get(h).copied().unwrap_or(0)),
                rule,
            )
        } else {
            let mu = c.map_or(0.0, |c| c.friction());
            (Side::Plain(mu.to_bits()), rule)
        }
    }

    fn side_law(&self, side: Side) -> Law {
        match side {
            Side::Material(id) => self.palette.get(id).law.clone(),
            Side::Plain(bits) => plain_law(f32::from_bits(bits) as f64),
        }
    }

    /// Whether any material (a collider's, the default, a pair's) resists rotation.
    pub fn any_rotation(&self) -> bool {
        self.palette
            .0
            .iter()
            .any(FrictionMaterial::resists_rotation)
            || self.pairs.values().any(FrictionMaterial::resists_rotation)
    }

    /// The rolling and spinning laws of the pair `(c1, c2)`, if its materials ask for any:
    /// the pair's own material's, else the attached sides' (both: combined by the pair's
    /// rule, like the friction law; an unattached side brings none).
    pub fn rotation_laws<'a>(
        &'a self,
        attached: &ColliderBits,
        colliders: &ColliderSet,
        (c1, c2): (ColliderHandle, ColliderHandle),
    ) -> Option<crate::rolling::RotationLaws<'a>> {
        use std::borrow::Cow;
        let laws = |rolling: Option<Cow<'a, Law>>, spinning: Option<Cow<'a, Law>>| {
            (rolling.is_some() || spinning.is_some())
                .then_some(crate::rolling::RotationLaws { rolling, spinning })
        };
        if let Some(m) = self.pairs.get(&pair_key(c1, c2)) {
            return laws(
                m.rolling.as_ref().map(Cow::Borrowed),
                m.spinning.as_ref().map(Cow::Borrowed),
            );
        }
        if !attached.contains(c1) && !attached.contains(c2) {
            return None;
        }
        let ((s1, r1), (s2, r2)) = (
            self.side(attached, colliders, c1),
            self.side(attached, colliders, c2),
        );
        let rule = r1.effective(r2);
        let material = |s: Side| match s {
            Side::Material(id) => Some(self.palette.get(id)),
            Side::Plain(_) => None,
        };
        let (m1, m2) = (material(s1), material(s2));
        let pick = |a: Option<&'a Law>, b: Option<&'a Law>| match (a, b) {
            (Some(a), Some(b)) if a == b => Some(Cow::Borrowed(a)),
            (Some(a), Some(b)) => Some(Cow::Owned(a.combine_or_coulomb(b, rule).0)),
            (Some(x), None) | (None, Some(x)) => Some(Cow::Borrowed(x)),
            (None, None) => None,
        };
        laws(
            pick(
                m1.and_then(|m| m.rolling.as_ref()),
                m2.and_then(|m| m.rolling.as_ref()),
            ),
            pick(
                m1.and_then(|m| m.spinning.as_ref()),
                m2.and_then(|m| m.spinning.as_ref()),
            ),
        )
    }

    /// Runs `f` on the law of the pair `(c1, c2)` (which must have an `attached` collider).
    pub fn with_pair_law<R>(
        &self,
        attached: &ColliderBits,
        colliders: &ColliderSet,
        (c1, c2): (ColliderHandle, ColliderHandle),
        warned: &Warned,
        f: impl FnOnce(&Law) -> R,
    ) -> R {
        if !self.pairs.is_empty()
            && let Some(m) = self.pairs.get(&pair_key(c1, c2))
        {
            return f(&m.law);
        }
        let ((s1, r1), (s2, r2)) = (
            self.side(attached, colliders, c1),
            self.side(attached, colliders, c2),
        );
        let rule = r1.effective(r2);
        if let (Side::Material(a), Side::Material(b)) = (s1, s2)
            && a == b
            && rule.is_idempotent()
        {
            return f(&self.palette.get(a).law);
        }
        let key = if s1 <= s2 {
            (s1, s2, rule)
        } else {
            (s2, s1, rule)
        };
        let shard = self.combined.shard();
        {
            let cache = shard.read();
            if let Some(law) = cache.get(&key) {
                return f(law);
            }
        }
        let mut cache = shard.write();
        if cache.len() >= MAX_COMBINATIONS && !cache.contains_key(&key) {
            cache.clear();
        }
        let law = cache.entry(key).or_insert_with(|| {
            let (a, b) = (self.side_law(key.0), self.side_law(key.1));
            let (law, error) = a.combine_or_coulomb(&b, rule);
            if let Some(e) = error {
                warned.once(
                    Warning::Combine,
                    &format!(
                        "stickslip: the materials of colliders {c1:?} and {c2:?} do not \
                         combine by {rule:?} ({e}); the pair uses plain Coulomb friction"
                    ),
                );
            }
            law
        });
        // Held for this one contact's step, once per new combination.
        f(law)
    }
}

/// Shards of the combination cache: one per thread up to this many.
const SHARDS: usize = 8;

/// The combination cache (see the module docs), one copy per thread (up to [`SHARDS`],
/// filled as each thread meets a combination): a read lock writes its count of readers, so
/// threads that read one lock for every contact they step (the hook in rapier's parallel
/// narrow phase, the pass after the step) would pass its cache line between cores. A
/// combination's law depends on its key alone, so the copies agree.
#[derive(Debug, Default)]
pub(crate) struct Combined {
    shards: [Shard; SHARDS],
}

/// A copy of the cache, on a cache line of its own.
#[derive(Debug, Default)]
#[repr(align(128))]
struct Shard(parking_lot::RwLock<HashMap<CombineKey, Law>>);

impl Combined {
    /// The running thread's copy.
    fn shard(&self) -> &parking_lot::RwLock<HashMap<CombineKey, Law>> {
        use std::sync::atomic::{AtomicUsize, Ordering};
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        thread_local! {
            static SHARD: usize = NEXT.fetch_add(1, Ordering::Relaxed) % SHARDS;
        }
        &self.shards[SHARD.with(|s| *s)].0
    }

    /// Heap bytes held (capacity included) by every copy.
    fn heap_bytes(&self) -> usize {
        self.shards
            .iter()
            .map(|s| crate::heap::map_bytes(&s.0.read()))
            .sum()
    }
}

/// Per-pair overrides.
pub(crate) type PairMaterials = HashMap<(ColliderHandle, ColliderHandle), FrictionMaterial>;
