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

## 導出した設計（design=derived）：各値を与える規則とその理由。
# $voltage：定格線間電圧（V 実効値）、$frequency：定格周波数（Hz）。
design-rule-vdc = √2 × { $voltage } V、整流した線間電圧。vlimit=circle なので、電圧制限は定格相電圧の振幅 vdc/√3 です
design-rule-flux = { $voltage } V、{ $frequency } Hz、無負荷での回転子磁束 M·V/|Rs + jωLs|：電動機自身の励磁です
design-rule-flux-capped = M·i_rated/√2 で頭打ち（{ $voltage } V、{ $frequency } Hz の無負荷磁束はこれより大きい）：励磁電流が i_rated² の半分をトルクに残します
design-rule-psi = 磁束の二乗、φa² + φb² の目標値
design-rule-id = 励磁電流、flux/M
# $i_rated：定格電流の振幅（A）。
design-rule-iq = トルク電流 √({ $i_rated }² − i_d²)：定格電流の残りの分
design-rule-torque = 定格電流・定格磁束でのトルク (3/2)·np·(M/Lr)·flux·i_q
design-rule-accel = 定格加速度 torque/J：定格電流で電動機が行える反転の傾き
# $share：電圧制限に対する百分率。
design-rule-base = 基底速度：ここで定格磁束と定格トルク電流は定常状態で電圧制限の{ $share } %を要します。これより上では fw=1 が磁束を base/ω に比例して下げて逆起電力を保ち、残りの電圧は電流ループの余裕になります
# $kts：k·Ts、$share：電圧制限に対する百分率、$sigma：漏れインダクタンス σ（H）。
design-rule-gain-ts = k2 = k3 = k4 = { $kts }/Ts：各誤差は一サンプルで自身の{ $kts }倍だけ減ってよく、論文の 20 kHz での 1200/s と同じです。電圧による上限（制限の{ $share } %を σ·i_rated で割った値、σ = { $sigma } H）はこれより高くなります
design-rule-gain-voltage = k2 = k3 = k4 = 電圧制限の{ $share } %を σ·i_rated で割った値（σ = { $sigma } H）：定格電流の大きさの誤差をこの速さで縮めるには電圧の四分の一を要します。サンプリングによる上限 { $kts }/Ts はこれより高くなります
# $ratio：k1 を k2 で割った比。
design-rule-k1 = k1 = { $ratio } × k2：速度ループは、それが指令する電流より遅くなります
design-rule-q = プロセスノイズ：モデルは電動機そのもので、プラントと同じく積分されるので、Q はフィルタのゲインを保つための下限にすぎません。論文の 1e-3 では、これらの電動機の NIS がその区間を下回ります
design-rule-r = 電流センサのノイズ：R をこれに合わせます
design-rule-r-none = センサ雑音なし：r_std = i_rated/1000 とし、フィルタのゲインを有限に保つ
# $time：秒。
design-rule-q-load = torque²/{ $time } s：負荷は{ $time } sで定格トルク分だけ変化しうるものとします
design-rule-load-std = torque/4：負荷は初め、定格トルクの四分の一の範囲で未知とします
# シナリオが design=derived のとき、プリセットの説明の下に表示する。
design-derived-heading = 電動機から導出した設計と、各値を与える規則
# $reason：コアが設計を導出できなかった理由。
design-failed = 導出した設計を表示できませんでした：{ $reason }

## 銘板と試験データから求める電動機（`imlab motor`、「解析」タブ）

# $key はフィールド（rs、no-load、locked、nema、rated、j、np）、$value は入力された値。
identify-bad-field = '{ $key }' = '{ $value }'：期待される値：{ $expected }
identify-expect-positive = 正の数
identify-expect-whole = 1以上の整数
identify-expect-nema = A、B、C、D のいずれか
identify-expect-rated = V,F,I：定格線間電圧（V 実効値）、定格周波数（Hz）、定格電流（A 実効値）をカンマで区切ったもの。いずれも正の値
identify-expect-reading = V,I,P,F：線間電圧（V 実効値）、線電流（A 実効値）、入力電力（W）、周波数（Hz）をカンマで区切ったもの。電力は 0 でもよく、その他は正の値
# $what はコードでの測定量の名前（voltage、current、frequency、power、rs）。
identify-not-positive = { $what } は正の数でなければなりません
# $test は試験のフィールド：no-load または locked。
identify-power-too-high = '{ $test }'：試験の電力が √3·V·I で供給できる値を超えているため、抵抗がインピーダンスより大きくなってしまいます
identify-no-rotor-resistance = 'locked'：拘束試験での一相あたりの抵抗 { $locked } Ω が固定子の { $rs } Ω 以下なので、回転子抵抗が残りません
identify-no-magnetising = 'no-load'：無負荷リアクタンスが固定子の漏れリアクタンス以下なので、励磁リアクタンスが残りません
# $stator と $rotor は漏れの配分（0.5 と 0.5）、$letter は NEMA デザインの記号。
identify-heading = 無負荷試験と拘束試験（IEEE Std 112）から求めた等価回路。拘束試験の漏れを固定子と回転子に { $stator }/{ $rotor } で配分（NEMA デザイン { $letter }）
identify-how-rs = 直流試験
identify-how-rr = 推定値：拘束試験の抵抗から rs を引き、励磁枝を介して回転子抵抗に換算した値
identify-how-m = 推定値：無負荷リアクタンスから固定子の漏れを引いた値
identify-how-ls = 推定値：m に、拘束試験の漏れのうち固定子の分を加えた値
identify-how-lr = 推定値：m に、拘束試験の漏れのうち回転子の分を加えた値
identify-how-given = 与えられた値
identify-link-heading = プリセット step の電動機（プラントとモデルの両方）、その定格と導出した設計：
