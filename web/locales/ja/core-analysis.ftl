sweep-not-settled = 整定していません：最後の { $periods } 周期で、前半から後半にかけて ω のゲインが { $gain } dB、位相が { $phase }° 変化しました（整定の基準：±{ $gain-bound } dB および ±{ $phase-bound }° 以内）
