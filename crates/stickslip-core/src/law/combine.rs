//! One law for a pair of surfaces: how two materials' friction laws combine.
//!
//! rapier, PhysX, Jolt, Box2D and avian give each collider a friction coefficient and combine
//! two of them with a rule; stickslip does the same for every coefficient of a law:
//!
//! - **Coefficients** (μ_ba, μ_max, the sliding curve μ_ve(v) point by point, Coulomb's μ)
//!   combine by [`CombineRule`], rapier's rules with rapier's precedence when the two sides
//!   disagree (GeometricMean > ClampedSum > Max > Multiply > Min > Average). Every rule is
//!   non-decreasing in each argument, so μ_ba ≤ μ_max on both sides stays true for the pair.
//! - **Stiffness** c (k_t = c·F_n) of two elasto-plastic surfaces: the harmonic mean
//!   2 c₁c₂/(c₁ + c₂). A material's c is measured, as in the seed, for a pair of like
//!   surfaces, i.e. two equal surface layers of stiffness 2c in series; unlike surfaces are
//!   one layer of each in series: 1/c = 1/(2c₁) + 1/(2c₂). A side without a compliance model
//!   (a rigid law, or a plain collider) leaves the compliant side's c (nothing is known of its
//!   layer, so it counts as alike).
//! - **Law kind**: the more detailed model of the two models the pair, EP > Phys > Regul >
//!   Coulomb. A side of a simpler kind takes part with what it has: its break-away
//!   coefficient for μ_ba and μ_max (a rigid law breaks away where it peaks) and its sliding
//!   curve (Coulomb: constant μ; Regul: its curve). Regul's v_reg and Phys's stick speed come
//!   from the side(s) that have one (two: the larger, the softer regularization); EP's literal
//!   variant only when both sides are literal EP.
//! - The result never depends on which side is first, and a material combined with itself by
//!   an idempotent rule (Average, Min, Max, GeometricMean) is that material, exactly.

use super::{
    Coulomb, ElastoPlastic, EpVariant, FrictionLaw, Law, Physical, Regularization, Regularized,
};
use crate::ParamError;
use crate::combine_rule::CombineRule;
use crate::sliding_curve::{Curve, SlidingCurve};

impl Curve {
    /// The sliding curve of a pair: the two curves combined point by point by `rule`.
    pub fn combine(&self, other: &Curve, rule: CombineRule) -> Curve {
        match (self, other) {
            _ if self == other && rule.is_idempotent() => self.clone(),
            (Curve::Constant { mu: a }, Curve::Constant { mu: b }) => Curve::Constant {
                mu: rule.apply(*a, *b),
            },
            _ => {
                // A canonical order: the same curve whichever side is first.
                let (a, b) = if serde_key(self) <= serde_key(other) {
                    (self, other)
                } else {
                    (other, self)
                };
                Curve::Combined {
                    rule,
                    curves: Box::new([a.clone(), b.clone()]),
                }
            }
        }
    }
}

/// An order of curves that does not depend on which side a curve came from.
fn serde_key(c: &Curve) -> String {
    format!("{c:?}")
}

/// What a law brings to a pair (see the module docs).
struct Parts<'a> {
    kind: u8,
    mu_ba: f64,
    mu_max: f64,
    curve: std::borrow::Cow<'a, Curve>,
    c: Option<f64>,
    literal: bool,
    v_reg: Option<(f64, Regularization)>,
    stick_speed: Option<f64>,
}

fn parts(law: &Law) -> Parts<'_> {
    use std::borrow::Cow;
    match law {
        Law::ElastoPlastic(l) => Parts {
            kind: 3,
            mu_ba: l.mu_ba(),
            mu_max: l.mu_max(),
            curve: Cow::Borrowed(l.curve()),
            c: Some(l.c()),
            literal: l.variant() == EpVariant::Literal,
            v_reg: None,
            stick_speed: None,
        },
        Law::Physical(l) => Parts {
            kind: 2,
            mu_ba: l.mu_ba(),
            mu_max: l.mu_ba(),
            curve: Cow::Borrowed(l.curve()),
            c: None,
            literal: false,
            v_reg: None,
            stick_speed: Some(l.stick_speed()),
        },
        Law::Regularized(l) => Parts {
            kind: 1,
            mu_ba: l.curve().at_rest(),
            mu_max: l.curve().at_rest(),
            curve: Cow::Borrowed(l.curve()),
            c: None,
            literal: false,
            v_reg: Some((l.v_reg(), l.shape())),
            stick_speed: None,
        },
        Law::Coulomb(l) => Parts {
            kind: 0,
            mu_ba: l.mu(),
            mu_max: l.mu(),
            curve: Cow::Owned(Curve::Constant { mu: l.mu() }),
            c: None,
            literal: false,
            v_reg: None,
            stick_speed: None,
        },
    }
}

/// Both, one or none of two optional values, reduced by `f`.
fn either<T: Copy>(a: Option<T>, b: Option<T>, f: impl Fn(T, T) -> T) -> Option<T> {
    match (a, b) {
        (Some(x), Some(y)) => Some(f(x, y)),
        (x, None) | (None, x) => x,
    }
}

impl Law {
    /// The law of a contact between a surface of law `self` and one of law `other`, with
    /// coefficients combined by `rule` (module docs of [`crate::law`]'s `combine`). Symmetric;
    /// a law combined with itself by an idempotent rule is itself. Errors when a combined
    /// coefficient leaves the valid range (e.g. `Multiply` of two small coefficients).
    pub fn combine(&self, other: &Law, rule: CombineRule) -> Result<Law, ParamError> {
        if self == other && rule.is_idempotent() {
            return Ok(self.clone());
        }
        let (a, b) = (parts(self), parts(other));
        let mu_ba = rule.apply(a.mu_ba, b.mu_ba);
        let mu_max = rule.apply(a.mu_max, b.mu_max);
        let curve = a.curve.combine(&b.curve, rule);
        Ok(match a.kind.max(b.kind) {
            3 => {
                let c = either(a.c, b.c, |x, y| 2.0 * x * y / (x + y)).unwrap_or(f64::NAN);
                let law = ElastoPlastic::new(c, mu_ba, mu_max, curve)?;
                let literal = a.literal && b.literal;
                Law::ElastoPlastic(if literal {
                    law.with_variant(EpVariant::Literal)?
                } else {
                    law
                })
            }
            2 => {
                let law = Physical::new(mu_ba, curve)?;
                match either(a.stick_speed, b.stick_speed, f64::max) {
                    Some(s) => Law::Physical(law.with_stick_speed(s)?),
                    None => Law::Physical(law),
                }
            }
            1 => {
                let (v_reg, shape) = either(a.v_reg, b.v_reg, |x, y| {
                    let shape = if x.1 == y.1 {
                        x.1
                    } else {
                        Regularization::Tanh
                    };
                    (x.0.max(y.0), shape)
                })
                .unwrap_or((f64::NAN, Regularization::Linear));
                Law::Regularized(Regularized::new(curve, v_reg, shape)?)
            }
            _ => Law::Coulomb(Coulomb::new(mu_ba)?),
        })
    }

    /// The law of a pair as every engine adapter takes it: [`Law::combine`], or, where a
    /// combined coefficient leaves the valid range, plain Coulomb friction at the two
    /// break-away coefficients combined by `rule`, clamped into range. The error says why it
    /// fell back (the adapters warn once).
    pub fn combine_or_coulomb(&self, other: &Law, rule: CombineRule) -> (Law, Option<ParamError>) {
        match self.combine(other, rule) {
            Ok(law) => (law, None),
            Err(e) => {
                let mu = rule.apply(self.static_coefficient(), other.static_coefficient());
                (Law::Coulomb(Coulomb::clamped(mu)), Some(e))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sliding_curve::StribeckDecay;

    #[test]
    fn a_pair_out_of_range_falls_back_to_clamped_coulomb() {
        let a = Law::Coulomb(Coulomb::new(1e-4).unwrap());
        let b = Law::elasto_plastic(1e4, 1e-4, 1e-4, Curve::constant(1e-4).unwrap()).unwrap();
        let (law, err) = a.combine_or_coulomb(&b, CombineRule::Multiply);
        assert!(err.is_some(), "1e-8 is below the smallest coefficient");
        assert_eq!(law, Law::Coulomb(Coulomb::clamped(1e-8)));
        assert_eq!(law.static_coefficient(), crate::error::MIN_COEFFICIENT);
        let (law, err) = a.combine_or_coulomb(&b, CombineRule::Average);
        assert!(err.is_none());
        assert_eq!(law, a.combine(&b, CombineRule::Average).unwrap());
    }

    fn laws() -> Vec<Law> {
        let stribeck = Curve::stribeck(0.6, 0.4, 0.01, StribeckDecay::Gaussian, 0.0).unwrap();
        vec![
            Law::elasto_plastic(1e4, 0.3, 0.35, Curve::constant(0.35).unwrap()).unwrap(),
            Law::elasto_plastic(4e4, 0.5, 0.6, stribeck.clone()).unwrap(),
            Law::ElastoPlastic(
                ElastoPlastic::new(2e4, 0.4, 0.5, Curve::constant(0.5).unwrap())
                    .unwrap()
                    .with_variant(EpVariant::Literal)
                    .unwrap(),
            ),
            Law::Physical(Physical::new(0.5, stribeck.clone()).unwrap()),
            Law::Regularized(
                Regularized::new(Curve::constant(0.4).unwrap(), 1e-3, Regularization::Tanh)
                    .unwrap(),
            ),
            Law::Coulomb(Coulomb::new(0.2).unwrap()),
        ]
    }

    const RULES: [CombineRule; 6] = [
        CombineRule::Average,
        CombineRule::Min,
        CombineRule::Multiply,
        CombineRule::Max,
        CombineRule::ClampedSum,
        CombineRule::GeometricMean,
    ];

    #[test]
    fn symmetric_and_idempotent() {
        for a in laws() {
            for b in laws() {
                for rule in RULES {
                    let (ab, ba) = (a.combine(&b, rule), b.combine(&a, rule));
                    assert_eq!(ab, ba, "{a:?} {b:?} {rule:?}");
                }
            }
            for rule in RULES.into_iter().filter(|r| r.is_idempotent()) {
                assert_eq!(a.combine(&a, rule).unwrap(), a);
            }
        }
    }

    #[test]
    fn coefficients_stiffness_and_kind() {
        let l = laws();
        // EP (c 1e4, 0.3/0.35) with EP (c 4e4, 0.5/0.6, Stribeck 0.6 → 0.4).
        let Law::ElastoPlastic(e) = l[0].combine(&l[1], CombineRule::Average).unwrap() else {
            panic!("EP with EP is EP");
        };
        assert!((e.c() - 2.0 * 1e4 * 4e4 / 5e4).abs() < 1e-9);
        assert!((e.mu_ba() - 0.4).abs() < 1e-15);
        assert!((e.mu_max() - 0.475).abs() < 1e-15);
        for v in [0.0, 0.005, 0.01, 0.1, 10.0] {
            let want = 0.5 * (0.35 + l[1].as_dyn().sliding_coefficient(v));
            assert!((e.curve().mu(v) - want).abs() < 1e-15, "{v}");
        }
        assert_eq!(e.variant(), EpVariant::Latched);
        // EP with plain Coulomb 0.2 under Min: c kept, coefficients clipped at 0.2.
        let Law::ElastoPlastic(e) = l[0].combine(&l[5], CombineRule::Min).unwrap() else {
            panic!("EP with Coulomb is EP");
        };
        assert_eq!((e.c(), e.mu_ba(), e.mu_max()), (1e4, 0.2, 0.2));
        assert_eq!(e.curve().mu(1.0), 0.2);
        // Two literal EPs stay literal.
        let Law::ElastoPlastic(e) = l[2].combine(&l[2], CombineRule::Multiply).unwrap() else {
            panic!()
        };
        assert_eq!(e.variant(), EpVariant::Literal);
        assert!((e.mu_ba() - 0.16).abs() < 1e-15 && (e.mu_max() - 0.25).abs() < 1e-15);
        // Phys with Regul is Phys; Regul with Coulomb is Regul (its v_reg, its shape).
        assert!(matches!(
            l[3].combine(&l[4], CombineRule::Max).unwrap(),
            Law::Physical(p) if p.mu_ba() == 0.5
        ));
        assert!(matches!(
            l[4].combine(&l[5], CombineRule::Max).unwrap(),
            Law::Regularized(r) if r.v_reg() == 1e-3 && r.shape() == Regularization::Tanh
                && r.curve().mu(1.0) == 0.4
        ));
        // Out of range: Multiply of two tiny coefficients is an error, not a law.
        let tiny = Law::Coulomb(Coulomb::new(1e-4).unwrap());
        assert!(tiny.combine(&tiny, CombineRule::Multiply).is_err());
    }

    #[test]
    fn rules_match_rapier() {
        // Rapier's CoefficientCombineRule::combine, written out.
        assert_eq!(CombineRule::Average.apply(0.2, 0.6), 0.4);
        assert_eq!(CombineRule::Min.apply(0.2, 0.6), 0.2);
        assert!((CombineRule::Multiply.apply(0.2, 0.6) - 0.12).abs() < 1e-16);
        assert_eq!(CombineRule::Max.apply(0.2, 0.6), 0.6);
        assert_eq!(CombineRule::ClampedSum.apply(0.7, 0.6), 1.0);
        assert!((CombineRule::GeometricMean.apply(0.2, 0.8) - 0.4).abs() < 1e-16);
        assert_eq!(
            CombineRule::Average.effective(CombineRule::Max),
            CombineRule::Max
        );
        assert_eq!(
            CombineRule::GeometricMean.effective(CombineRule::ClampedSum),
            CombineRule::GeometricMean
        );
    }
}
