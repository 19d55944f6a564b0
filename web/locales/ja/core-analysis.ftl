sweep-not-settled = 整定していません：最後の { $periods } 周期で、前半から後半にかけて ω のゲインが { $gain } dB、位相が { $phase }° 変化しました（整定の基準：±{ $gain-bound } dB および ±{ $phase-bound }° 以内）

## モデル誤差マップの軸とシード：却下される理由と、軸の名前。
map-axis-form = 軸 '{ $axis }'：KEY=LO..HI:N の形で指定してください（例：plant.rr=-10%..+10%:11、k1=-20%..+20%:5）
map-axis-unknown = 軸 '{ $axis }'：{ $key } はシナリオのフィールドではありません
map-axis-not-numeric = 軸 '{ $axis }'：{ $key } は数値ではありません。マップで変化させられるのは数値のフィールドです
map-axis-whole = 軸 '{ $axis }'：{ $key } は整数しかとりません。連続値をとるフィールドをマップの軸にしてください
map-axis-inactive = 軸 '{ $axis }'：{ $key } はこのシナリオでは効果がないため、どのセルも同じ実行になってしまいます
map-axis-end = 軸 { $key }：{ $end } '{ $text }'：数値か、-10% のような百分率を指定してください
map-axis-mixed = 軸 '{ $axis }'：LO と HI は、両方とも値か、両方とも百分率でなければなりません
map-axis-count = 軸 { $key }：N '{ $text }'：1～{ $max }の整数を指定してください
map-axis-zero = 軸 '{ $axis }'：{ $other } が 0 なので、それに対する相対誤差も 0 になります。{ $key } は値で指定してください
map-axis-order = 軸 { $key }：LO（{ $lo }）が HI（{ $hi }）より大きくなっています
map-axis-against-model = モデルに対する { $key }（%）
map-axis-against-motor = 電動機に対する { $key }（%）
map-axis-against-base = 基準値に対する { $key }（%）
map-axis-unit = { $key }（{ $unit }）
map-seeds-form = シード '{ $seeds }'：A..B の形で、0～{ $max }の整数を指定してください
map-seeds-order = シード '{ $seeds }'：最初のシードが最後のシードより大きくなっています
map-seeds-many = シード '{ $seeds }'：{ $count }シードは、マップで実行できる{ $max }シードを超えています
map-seeds-twice = シードが二回指定されています。一回だけ指定してください
map-axes-count = 軸が{ $count }個あります。マップの軸は一つか二つです
map-axes-repeated = 両方の軸が { $key } を変化させています。異なる二つのフィールドを変化させてください
map-axes-sides = 軸が { $first } と { $second }、つまり一つのパラメータの両側を変化させています。片側だけを、値か、もう一方に対する相対誤差で変化させてください
map-no-seeds = シードがありません。マップは少なくとも一つのシードで実行します
map-runs-many = マップには{ $runs }回の実行（{ $cells }セル × { $seeds }シード）が必要で、許容される{ $max }回を超えています。点かシードを減らしてください
map-cell-refused = { $key }={ $value }：{ $reason }
map-work = マップにはプラントの{ $work }ステップ（{ $cells }セル × { $seeds }シード × 一回の実行のステップ数）が必要で、許容される{ $max }ステップを超えています。点かシードを減らすか、'duration' を短くしてください
map-law-work = マップの自作の制御則には{ $work }演算（{ $cells }セル × { $seeds }シード × 実行一回あたり最大{ $per-run }演算）が必要で、許容される{ $max }演算を超えています。実行を{ $runs }回（セル × シード）以下にするか、'duration' を短くするか、演算の少ない制御則にしてください
