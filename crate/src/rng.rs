//! A small, portable, seeded random-number generator (xoshiro256++ seeded by SplitMix64).
//!
//! Only integer arithmetic, IEEE-exact `sqrt` and `libm`'s `log` and `exp` are used, so the same
//! seed gives the same bits on every target (native and wasm32).

use std::sync::OnceLock;

/// xoshiro256++ generator with two Gaussian samplers: the Marsaglia polar method (scenario
/// version 1) and a 256-layer ziggurat (version 2), which draws one 64-bit number for nearly
/// every sample and needs no logarithm there.
#[derive(Clone, Debug)]
pub struct Rng {
    s: [u64; 4],
    spare: Option<f64>,
}

impl Rng {
    /// A generator whose stream is fixed by `seed`.
    pub fn new(seed: u64) -> Rng {
        let mut z = seed;
        let mut next = || {
            z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut x = z;
            x = (x ^ (x >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            x = (x ^ (x >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            x ^ (x >> 31)
        };
        Rng {
            s: [next(), next(), next(), next()],
            spare: None,
        }
    }

    /// Next raw 64-bit output.
    pub fn next_u64(&mut self) -> u64 {
        let s = &mut self.s;
        let result = s[0].wrapping_add(s[3]).rotate_left(23).wrapping_add(s[0]);
        let t = s[1] << 17;
        s[2] ^= s[0];
        s[3] ^= s[1];
        s[1] ^= s[2];
        s[0] ^= s[3];
        s[2] ^= t;
        s[3] = s[3].rotate_left(45);
        result
    }

    /// Uniform sample in [0, 1) with 53 random bits.
    pub fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Standard normal sample by the Marsaglia polar method: pairs of uniforms inside the unit
    /// disc, one logarithm and one square root for two samples.
    pub fn normal(&mut self) -> f64 {
        if let Some(z) = self.spare.take() {
            return z;
        }
        loop {
            let a = 2.0 * self.uniform() - 1.0;
            let b = 2.0 * self.uniform() - 1.0;
            let s = a * a + b * b;
            if s > 0.0 && s < 1.0 {
                let m = (-2.0 * libm::log(s) / s).sqrt();
                self.spare = Some(b * m);
                return a * m;
            }
        }
    }

    /// Standard normal sample by the ziggurat method (Marsaglia and Tsang, 2000) with 256 layers
    /// of equal area under exp(−x²/2). One 64-bit number gives the layer (its low 8 bits) and a
    /// signed uniform (its high 53 bits); the sample is accepted at once when it falls inside the
    /// layer's inner rectangle, about 99 % of the time. Otherwise it is tested against the curve
    /// (one `exp`), or, in the base layer, drawn from the tail beyond R by Marsaglia's method.
    pub fn ziggurat_normal(&mut self) -> f64 {
        let z = ziggurat();
        loop {
            let bits = self.next_u64();
            let i = (bits & 0xff) as usize;
            let u = 2.0 * ((bits >> 11) as f64 * (1.0 / (1u64 << 53) as f64)) - 1.0;
            let x = u * z.x[i];
            if x.abs() < z.x[i + 1] {
                return x;
            }
            if i == 0 {
                let tail = self.normal_tail();
                return if u < 0.0 { -tail } else { tail };
            }
            if z.f[i + 1] + self.uniform() * (z.f[i] - z.f[i + 1]) < libm::exp(-0.5 * x * x) {
                return x;
            }
        }
    }

    /// A sample of the standard normal's tail beyond R, by Marsaglia's (1964) method.
    fn normal_tail(&mut self) -> f64 {
        loop {
            let a = -libm::log(self.uniform_open()) / ZIGGURAT_R;
            let b = -libm::log(self.uniform_open());
            if 2.0 * b > a * a {
                return ZIGGURAT_R + a;
            }
        }
    }

    /// Uniform sample in (0, 1): never 0, so its logarithm is finite.
    fn uniform_open(&mut self) -> f64 {
        ((self.next_u64() >> 11) as f64 + 0.5) * (1.0 / (1u64 << 53) as f64)
    }
}

/// Where the base layer's tail starts: the R for which 256 layers of equal area close at the
/// curve's peak (Marsaglia and Tsang's value).
const ZIGGURAT_R: f64 = 3.654_152_885_361_009;

/// The layers' right edges x_i (x_0 the base layer's equivalent width V/f(R), x_1 = R, down to
/// x_256 = 0) and the curve f(x) = exp(−x²/2) at each.
struct Ziggurat {
    x: [f64; 257],
    f: [f64; 257],
}

/// The area V of each layer under f(x) = exp(−x²/2): the base layer's rectangle [0, R] × [0,
/// f(R)] and the tail beyond R, ∫_R^∞ f = √(π/2)·erfc(R/√2).
fn layer_area() -> f64 {
    let r = ZIGGURAT_R;
    r * libm::exp(-0.5 * r * r)
        + (std::f64::consts::PI / 2.0).sqrt() * libm::erfc(r / std::f64::consts::SQRT_2)
}

/// The layers, computed once with `libm` (so the same bits on every target).
fn ziggurat() -> &'static Ziggurat {
    static LAYERS: OnceLock<Ziggurat> = OnceLock::new();
    LAYERS.get_or_init(|| {
        let f = |x: f64| libm::exp(-0.5 * x * x);
        let v = layer_area();
        let mut x = [0.0; 257];
        x[0] = v / f(ZIGGURAT_R);
        x[1] = ZIGGURAT_R;
        for i in 1..255 {
            x[i + 1] = (-2.0 * libm::log(v / x[i] + f(x[i]))).sqrt();
        }
        Ziggurat { x, f: x.map(f) }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normal_has_unit_moments() {
        // With n = 200k samples the standard error of the mean is 1/sqrt(n) ≈ 0.0022;
        // 5 standard errors keeps the test from flaking while still catching a wrong sampler.
        let n = 200_000;
        let mut rng = Rng::new(42);
        let (mut sum, mut sum2) = (0.0, 0.0);
        for _ in 0..n {
            let z = rng.normal();
            sum += z;
            sum2 += z * z;
        }
        let mean = sum / n as f64;
        let var = sum2 / n as f64 - mean * mean;
        assert!(mean.abs() < 5.0 / (n as f64).sqrt(), "mean {mean}");
        assert!(
            (var - 1.0).abs() < 5.0 * (2.0 / n as f64).sqrt(),
            "variance {var}"
        );
    }

    /// The standard normal CDF.
    fn phi(x: f64) -> f64 {
        0.5 * libm::erfc(-x / std::f64::consts::SQRT_2)
    }

    #[test]
    fn ziggurat_layers_have_equal_areas() {
        // Layer i ≥ 1 is the rectangle [0, x_i] × [f(x_i), f(x_{i+1})]. The table is built so that
        // layers 1 to 254 hold V; the last one, up to the peak f(0) = 1, holds V only for the
        // right R, and the base layer's equivalent rectangle x_0 × f(R) holds it by construction.
        let z = ziggurat();
        let v = layer_area();
        assert_eq!(z.x[256], 0.0);
        for i in 1..256 {
            assert!(z.x[i + 1] < z.x[i], "layer {i}");
            let area = z.x[i] * (z.f[i + 1] - z.f[i]);
            assert!((area / v - 1.0).abs() < 1e-12, "layer {i}: {area}");
        }
        assert!((z.x[0] * z.f[1] / v - 1.0).abs() < 1e-15);
    }

    #[test]
    fn ziggurat_samples_follow_the_normal_distribution() {
        // 10⁶ samples: the fraction below each x is within 5 standard errors of Φ(x), which holds
        // the body, each layer's edge region and, beyond R ≈ 3.65, the tail sampler; the moments
        // up to the fourth (3 for the normal) hold too.
        let n = 1_000_000;
        let mut rng = Rng::new(7);
        let points = [
            -4.0,
            -ZIGGURAT_R,
            -3.0,
            -2.0,
            -1.0,
            -0.3,
            0.0,
            0.3,
            1.0,
            2.0,
            3.0,
            ZIGGURAT_R,
            4.0,
        ];
        let mut below = [0usize; 13];
        let (mut m1, mut m2, mut m4) = (0.0, 0.0, 0.0);
        for _ in 0..n {
            let z = rng.ziggurat_normal();
            for (count, &x) in below.iter_mut().zip(&points) {
                *count += usize::from(z < x);
            }
            m1 += z;
            m2 += z * z;
            m4 += z * z * z * z;
        }
        let nf = n as f64;
        for (&count, &x) in below.iter().zip(&points) {
            let p = phi(x);
            let se = (p * (1.0 - p) / nf).sqrt();
            let seen = count as f64 / nf;
            assert!((seen - p).abs() < 5.0 * se, "P(z < {x}) = {seen}, Φ = {p}");
        }
        let (mean, var, kurt) = (m1 / nf, m2 / nf, m4 / nf);
        assert!(mean.abs() < 5.0 / nf.sqrt(), "mean {mean}");
        assert!(
            (var - 1.0).abs() < 5.0 * (2.0 / nf).sqrt(),
            "variance {var}"
        );
        // The fourth moment's standard error is √(105 − 9)/√n ≈ 9.8/√n.
        assert!(
            (kurt - 3.0).abs() < 5.0 * 96f64.sqrt() / nf.sqrt(),
            "fourth moment {kurt}"
        );
    }

    #[test]
    fn seeds_give_distinct_streams() {
        assert_ne!(Rng::new(1).next_u64(), Rng::new(2).next_u64());
    }
}
