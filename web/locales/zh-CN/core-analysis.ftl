sweep-not-settled = 未稳定：在最后 { $periods } 个周期中，从前一半到后一半，ω 的增益变化了 { $gain } dB，相位变化了 { $phase }°（稳定的标准：在 ±{ $gain-bound } dB 和 ±{ $phase-bound }° 以内）
