# 実行についてのコアの文言：各設定の意味、各プリセットが示すもの、実行の指標とそれぞれが対象とする
# 実行の部分、指標とともに読むべき警告、起動過渡の終わり、実行が止まった理由。キーとフィールド名
# （k1、law.v1、ekf.q）、フィールドの値（euler、rk4、box）、記号（ω_d、φa²、Rs、|i_s|）、単位、式、
# 論文の式番号と図番号（(38)、Fig 2）はリンクと論文自身の文言なので、そのまま残す。

## 時間

time-ms = { $ms } ms
time-s = { $s } s

## 各設定の意味（キー、単位、範囲はコーデック自身のもの）

# (0/1) はスイッチ：0 でオフ、1 でオン。

field-design = 設計：paper（論文、設定値のまま）または derived（電動機データから導出）
field-ref = 速度指令値の種類
field-ref-value = 一定速度
field-sine-amp = 正弦波の振幅
field-sine-freq = 正弦波の周波数
field-sine-offset = 正弦波に加える定数
field-step-size = ステップの大きさ
field-step-time = ステップの時刻
field-step-wn = ステップのフィルタの固有角周波数 ωn
field-ramp-start = ランプの開始時刻
field-ramp-level = ランプの平坦部の値
field-ramp-slope = ランプの傾きの大きさ
field-ramp-hold = ランプの平坦部の継続時間
field-rev-start = 反転の立ち上げ開始時刻
field-rev-level = 反転する速度、+level から −level へ
field-rev-slope = 反転の傾きの大きさ
field-rev-hold = 反転前に +level を保つ時間
field-ref-table = 点 t:ω_d の表で与える指令値（点の間は直線で結ぶ）
field-psi_d = φa² + φb² の磁束目標値
field-fw = 基底速度以上で弱め界磁（0/1）
field-fw-base = 弱め界磁の基底速度
field-k1 = 速度誤差の減衰率 k1
field-k2 = トルク誤差の減衰率 k2 = a7 + a8 + k2s1
field-k3 = 磁束誤差の減衰率 k3
field-k4 = 磁束微分誤差の減衰率 k4
field-robust = ロバスト項 (38) と (53) を適用（0/1）
field-eps2 = (38)の ε2：z2·(v2s2 + d̃2) の上界
field-h2 = (38)の h2：|d̃2| の上界
field-eps4 = (53)の ε4：z4·(v4s2 + d̃4) の上界
field-h4 = (53)の h4：|d̃4| の上界
field-law-v1 = 自作のステップ1：仮想入力 v1（空欄：論文の(26)）
field-law-v2 = 自作のステップ2：v2（空欄：論文の(34)）
field-law-v3 = 自作のステップ3：仮想入力 v3（空欄：論文の(45)）
field-law-v4 = 自作のステップ4：v4（空欄：論文の(49)）
field-controller = backstepping（論文のバックステッピング）または ifoc（古典的なセンサレスFOCの比較基準）
field-ifoc-bw_i = IFOCの電流ループ帯域幅
field-ifoc-bw_w = IFOCの速度ループ帯域幅
field-ifoc-bw_mras = IFOCのMRAS速度推定器の帯域幅
field-ifoc-i_max = IFOCのq軸電流の制限
field-ifoc-ff = IFOCのトルクフィードフォワード J·ω̇_d + T0 + Cf·ω_d（0/1）
field-ekf = EKFの予測器：euler（論文）または rk4
field-ekf-q = プロセスノイズ Q = q·Ts·I、全状態に共通の一つの値：電流は A²/s、ωは (rad/s)²/s、磁束は Wb²/s
field-ekf-q_speed = 速度の状態だけに加えるプロセスノイズ、Q_ωω = (q + q_speed)·Ts
field-ekf-r_std = 想定する電流ノイズ、R = r_std²·I
field-ekf-load = 負荷 a2 = T_L0/J をEKFの状態として推定（0/1）
field-ekf-q_load = 負荷トルクのランダムウォークの強度
field-ekf-load_std = 負荷推定値の初期標準偏差
field-ekf-rr = 回転子抵抗 R_r をEKFの状態として推定（0/1）
field-ekf-q_rr = 回転子抵抗のランダムウォークの強度
field-ekf-rr_std = R_r推定値の初期標準偏差
field-init_err = 推定値の初期相対誤差
field-start = 初期状態：paper（2 A、2 A、0.5 Wb、0.5 Wb）または magnetized（磁束目標値まで励磁）
field-perfect = 理想オブザーバ：制御器が真の状態を得る（0/1）
field-noise = 電流測定ノイズの標準偏差
field-seed = ノイズのシード
# シミュレーション上の電動機（プラント）のパラメータ。モデルのもの（制御器とオブザーバの想定）も同じ文言。
field-motor = プラントとモデルの電動機をまとめて選び、その定格電流も設定します
field-plant-rs = 固定子抵抗 Rs
field-plant-rr = 回転子抵抗 Rr
field-plant-m = 相互インダクタンス M
field-plant-ls = 固定子インダクタンス Ls
field-plant-lr = 回転子インダクタンス Lr
field-plant-j = 回転子の慣性モーメント J
field-plant-np = 極対数 np
field-plant-t0 = 一定の負荷トルク T0
field-plant-cf = 粘性摩擦係数 Cf
field-model-rs = { field-plant-rs }
field-model-rr = { field-plant-rr }
field-model-m = { field-plant-m }
field-model-ls = { field-plant-ls }
field-model-lr = { field-plant-lr }
field-model-j = { field-plant-j }
field-model-np = { field-plant-np }
field-model-t0 = { field-plant-t0 }
field-model-cf = { field-plant-cf }
field-load-time = 未知の負荷ステップの時刻
field-load-torque = 未知の負荷ステップの大きさ
field-load-table = 点 t:torque の表で与える未知の負荷トルク（点の間は直線で結ぶ。ステップの代わり）
field-vmax = 成分ごとの電圧制限
field-duration = シミュレーション時間
field-ts = サンプリング周期 Ts
field-substeps = サンプルあたりのプラントのRK4サブステップ数
field-i_rated = 定格電流：定格相電流の振幅 |i_s|
field-rated-v = 定格電圧（線間実効値）
field-rated-f = 定格周波数
field-delay = 計算遅延：u_k を一サンプル後に印加（0/1）
field-delay-comp = 遅延補償：一段先予測 x̂(k+1|k) から制御（0/1）
field-vlimit = 電圧制限：box（成分ごとに ±vmax、論文）、circle（|u| ≤ vdc/√3）、hex（二レベルインバータ）
field-vdc = circle・hex の制限とPWMの直流リンク電圧
field-pwm = 二レベルインバータ、サンプリング周波数の対称PWM（0/1、vlimit は circle か hex）

## 各プリセットが示すもの（preset-NAME：プリセット NAME）

# 説明の中のプリセット名（sine200、load-step、rr-mismatch）はリンクの文言なので、そのまま残す。

preset-sine200 = 論文 Fig 2：EKFを用いて 0.5 sin(2π·200 t) rad/s に追従。電流のピーク値は電動機の定格電流を超える
preset-step = 論文 Fig 3：50 msに 0 → 0.5 rad/s のステップ（200 Hzの臨界減衰フィルタを通す）
preset-ramp = 論文 Fig 4：±400 rad/s²で100 rad/sまで上げ、保持して戻す台形
preset-sine200-1rad = 200 Hzで1 rad/s：400 Vの制限で飽和し、追従誤差はsine200の三倍を超える
preset-sine200-rk4 = Fig 2 で、EKFの予測器を論文のオイラーではなくRK4にしたもの
preset-rr-mismatch = 50 rad/sを保持。電動機の回転子抵抗はモデルより10 %大きい：真の速度は起動から数秒かけて回復し、指令値より上で整定する（終わりまで見るには6 sで実行）
preset-load-step = 50 rad/sを保持。0.15 sに未知の2 N mの負荷ステップが加わり、5状態のEKFにはそれが見えない
preset-decay = 理想オブザーバ、ノイズなし、ω_d ≡ 0：誤差は設計どおり1200/sで減衰し、その後、サンプリング周期とともに小さくなる下限で止まる
preset-ifoc-step = 古典的な比較基準：MRASを用いたセンサレスIFOC、40 rad/sへのステップ（MRASはゼロ速度付近では速度を推定できない）
preset-load-step-est = load-stepで負荷 a2 をEKFの状態にしたもの（RK4予測器）：モデルが正確なら未知のステップでも速度は保たれるが、電動機のR_rがモデルより3 %小さいと保たれない
preset-rr-mismatch-est = rr-mismatchでR_rをEKFの状態にしたもの（RK4予測器）：遅い過渡はなく、R̂_rは電動機の値の近くにとどまる
preset-sine200-drive = 200 Hzは実際のドライブでも成り立つか？ 一サンプルの計算遅延、540 Vのインバータの六角形、PWMを加えたsine200
preset-high-gain = ゲイン3000/s（論文の2.5倍）：オイラーEKFの予測誤差がゲインを通して400 Vの制限を飽和させる

## 実行の指標（`imlab metrics` は figure- の後の部分で呼ぶ）

figure-transient_end = 起動過渡の終了
figure-tracking_rms = ω − ω_dのRMS
figure-tracking_peak = |ω − ω_d|のピーク値
figure-settling_time = ステップ後のωの2 %整定時間
figure-saturated_share = 電圧制限に達したサンプルの割合
figure-mean_nis = 平均NIS
figure-mean_nis_low = 平均NIS、整合したフィルタの95 %区間の下端
figure-mean_nis_high = 平均NIS、整合したフィルタの95 %区間の上端
figure-current_peak = 固定子電流のピーク値 |i_s|
figure-current_rms = 固定子電流のRMS |i_s|
figure-current_rated = 定格電流 |i_s|（i_rated）
figure-ripple_peak = PWM電流リプルのピーク値
figure-ripple_rms = PWM電流リプルの各周期のピーク値のRMS
figure-flux_error_final = 最終磁束誤差 |φ_r| − √ψ_d
figure-speed_error_final = 最終速度誤差 ω − ω_d
figure-speed_estimate_error_final = 最終速度推定誤差 ω − ω̂
figure-law_residual = 自作の制御則の設計ダイナミクスに対する最大残差（実行全体と判定で抽出した状態にわたる、論文の制御則に対する相対値）
# 実行の指標には含まれない：課題が指定できる。
figure-load_recovery_time = 負荷ステップ後の回復時間

## 指標が対象とする実行の部分

window-after-transient = t ≥ { $time }
window-start-up = 起動時、t < { $time }
window-from-step = { $time }のステップから
window-rating = 電動機の定格
window-last-sample = 最後のサンプル、t = { $time }
window-law-residual = 実行全体と、判定で抽出した状態

## 実行終了までに到達しなかった指標（値の代わりに表示）

unreached-not-settled = 実行終了までに整定せず（t = { $time }）

## 実行の指標とともに読むべき警告

warning-runaway = 実行が暴走しました：終了時、真の速度は指令値から{ $speed } rad/s、速度推定値は真の速度から{ $estimate } rad/s離れ、磁束は目標値{ $target } Wbに対して{ $flux } Wbです。制御器が調節するのはEKFの推定値です。定理4.6が閉ループを有界とするのは推定誤差が有界にとどまる間だけで、そうでないとき（電圧制限だけで抑えられている起動時の誤差、低速でのモデルの誤り）は、電動機を有界に保つものは何もありません。
warning-inconsistent-above = この実行ではEKFが非整合です：平均NISは{ $nis }で、モデルが合っているフィルタの95 %区間 { $low }–{ $high } を大きく上回っています。その推定値と、制御器が用いる速度は、帯がどれほど狭く見えても真値から大きく離れているおそれがあります。
warning-inconsistent-below = この実行ではEKFが非整合です：平均NISは{ $nis }で、モデルが合っているフィルタの95 %区間 { $low }–{ $high } を大きく下回っています。実際より大きなノイズを想定しているため、可能な速さよりもゆっくり測定値に追従します。
warning-not-following = 速度が指令値に追従していません：t = { $since } から実行の終わりまで、ω − ω_d は ±(|ω_d| の { $share } % + { $margin } rad/s) の外にあり、終了時は ω_d = { $reference } rad/s に対して { $error } rad/s です。
warning-not-following-window = 速度が指令値に追従していません：指標の窓全体、すなわち t = { $since } から実行の終わりまで、ω − ω_d は ±(|ω_d| の { $share } % + { $margin } rad/s) の外にあり、終了時は ω_d = { $reference } rad/s に対して { $error } rad/s です。
warning-not-finite = { $figure } は有限の数ではありません：{ $cause }。

## 起動過渡が終わる時刻と、その理由

transient-nothing-recorded = まだ何も記録されていません
transient-never = 前半では成立せず、不使用
transient-backstepping = 最も遅い設計誤差減衰率の時定数（1/{ $k } s）の5倍 = { $time }
transient-ifoc = IFOCの電流ループの時定数（1/(2π·{ $bw } Hz)）の5倍 = { $time }
transient-reason =
    { $controller }（オブザーバの起動から数える）。EKFのイノベーション共分散の整定（2σ帯が最終値の10 %以内）：{ $observer }。EKFの推定値の収束（2 ms区間の平均NISが後半の水準の二倍以内、5 ms間）：{ $estimates }。磁束推定値が以後のRMS誤差の1.5倍以内（5 ms間）：{ $flux }。速度推定値が以後のRMS誤差の二倍以内（5 msの窓、5 ms間）：{ $speed }{ $end ->
        [event] 。シナリオの最初のイベント（{ $at }）で打ち切り
        [half] 。記録した実行の半分（{ $at }）までに制限
       *[none] {""}
    }

## 実行が止まった理由

sim-diverged = t = { $t } sで発散：{ $signal } = { $value } が範囲を外れました
sim-not-finite = t = { $t } sで停止：列 '{ $column }' に有限でない値 { $value } が記録されるところでした
sim-control = t = { $t } sで制御器が失敗：{ $error }
sim-law = あなたの law.v{ $step } = { $formula } は t = { $t } s で { $value } を返しました（{ $reading }）
sim-law-reads-nothing = どの信号も読んでいません
sim-law-reads = 読んだ値：{ $signals }
control-singular = 非干渉化行列 (55) が特異です：推定磁束 x̂4² + x̂5² = { $flux } Wb² が { $min } Wb² を下回っています
control-law = ステップ{ $step }の制御則が有限の数ではない { $value } を返しました
pin-room-full = ピン留めできる実行は最大 { $max } 件です。先にどれかのピンを外してください
pin-legend-same = 同じシナリオ
overlay-ts-differs = ピン留めした実行 { $scenario } のサンプリング周期は Ts = { $pinned } s、現在の実行は { $current } s です。重ね描きには同じ Ts が必要です
