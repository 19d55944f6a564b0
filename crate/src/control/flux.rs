//! The flux target ψ_d and, with field weakening, its fall above base speed: ψ_d(ω_d) with the
//! two time derivatives that steps 3 and 4 use, eqs (42)–(47).

use super::RefSample;

/// The flux target at reference `r`: ψ_d without field weakening (`base` None), else weakened
/// above base speed `base` (rad/s) as ψ_d·(1 + y⁴)^(−1/4) with y = (ω_d/ω_b)²: ψ_d well below base
/// speed, ψ_d·(ω_b/ω_d)² well above it (the flux inversely proportional to the speed, so the
/// back-EMF stays at its base-speed value), and 2^(−1/4) = 84 % of ψ_d at base speed. Value
/// (Wb²), first and second time derivatives.
#[inline(never)]
pub fn flux_target(psi_d: f64, base: Option<f64>, r: &RefSample) -> RefSample {
    let Some(base) = base else {
        return RefSample {
            value: psi_d,
            d1: 0.0,
            d2: 0.0,
        };
    };
    let b2 = base * base;
    let y = r.value * r.value / b2;
    let dy = 2.0 * r.value * r.d1 / b2;
    let ddy = 2.0 * (r.d1 * r.d1 + r.value * r.d2) / b2;
    // g(y) = (1 + y⁴)^(−1/4), g' = −(1 + y⁴)^(−5/4)·y³ = −g⁵·y³,
    // g'' = (1 + y⁴)^(−9/4)·y²·(2·y⁴ − 3) = g⁹·y²·(2·y⁴ − 3): square roots and products only.
    let y2 = y * y;
    let y4 = y2 * y2;
    let g = 1.0 / (1.0 + y4).sqrt().sqrt();
    let g4 = g * g * g * g;
    let g5 = g4 * g;
    let g1 = -g5 * y2 * y;
    let g2 = g5 * g4 * y2 * (2.0 * y4 - 3.0);
    RefSample {
        value: psi_d * g,
        d1: psi_d * g1 * dy,
        d2: psi_d * (g2 * dy * dy + g1 * ddy),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::Reference;

    #[test]
    fn without_weakening_the_target_is_constant() {
        let r = RefSample {
            value: 300.0,
            d1: 50.0,
            d2: 1.0,
        };
        assert_eq!(
            flux_target(0.8, None, &r),
            RefSample {
                value: 0.8,
                d1: 0.0,
                d2: 0.0
            }
        );
    }

    #[test]
    fn weakening_keeps_the_flux_below_base_and_inverse_to_speed_above_it() {
        let at = |w: f64| {
            flux_target(
                1.0,
                Some(100.0),
                &RefSample {
                    value: w,
                    d1: 0.0,
                    d2: 0.0,
                },
            )
            .value
        };
        assert!((at(40.0) - 1.0).abs() < 1e-3, "{}", at(40.0));
        assert!((at(100.0) - 0.5f64.powf(0.25)).abs() < 1e-12);
        // Flux (the square root) within 1 % of ω_b/ω at 2.5 times base speed.
        assert!((at(250.0).sqrt() * 2.5 - 1.0).abs() < 0.01, "{}", at(250.0));
        assert_eq!(at(-150.0), at(150.0));
    }

    #[test]
    fn the_derivatives_are_those_of_the_target_along_a_reference() {
        let reference = Reference::Sine {
            amp: 150.0,
            freq: 3.0,
            offset: 20.0,
        };
        let target = |t: f64| flux_target(0.9, Some(120.0), &reference.sample(t));
        let h = 1e-6;
        for t in [0.01, 0.05, 0.08, 0.12, 0.2, 0.31] {
            let (p, m, c) = (target(t + h), target(t - h), target(t));
            let d1 = (p.value - m.value) / (2.0 * h);
            let d2 = (p.d1 - m.d1) / (2.0 * h);
            assert!(
                (d1 - c.d1).abs() <= 1e-5 * (1.0 + c.d1.abs()),
                "d1 at {t}: {d1} {}",
                c.d1
            );
            assert!(
                (d2 - c.d2).abs() <= 1e-4 * (1.0 + c.d2.abs()),
                "d2 at {t}: {d2} {}",
                c.d2
            );
        }
    }
}
