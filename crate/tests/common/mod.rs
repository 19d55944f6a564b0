//! What the challenge tests share: a small challenge with every kind of key, and its canonical
//! text.
#![allow(dead_code)]

/// A small challenge with every kind of key.
pub const SMALL: &str = "c=1&title=Quick%20step&base=v%3D1%26preset%3Dstep%26duration%3D0.08\
                     &allow.k2=300..3000&allow.k1=300..3000&allow.ekf=rk4|euler\
                     &need.settling_time=max:0.006&need.current_peak=max:4&need.mean_nis=band\
                     &vary=model.j%3D0.016|model.j%3D0.024&robust=current_peak";

/// SMALL's canonical text.
pub const SMALL_CANONICAL: &str =
    "c=1&title=Quick%20step&base=v%3D1%26preset%3Dstep%26duration%3D0.08\
     &allow.k1=300..3000&allow.k2=300..3000&allow.ekf=euler|rk4\
     &need.settling_time=max:0.006&need.current_peak=max:4&need.mean_nis=band\
     &vary=model.j%3D0.016|model.j%3D0.024&robust=current_peak";
