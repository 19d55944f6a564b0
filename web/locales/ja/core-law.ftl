# 各ステップの自作の制御則についてのコアのメッセージ：式が却下された理由と、ステップが与えるべき誤差
# ダイナミクスに照らした制御則の判定。名前（x1h、k1s1、v1、z2）、関数（sqrt）、式（ż1 = −k1·z1 + z2）、
# 設定（law.v1）、論文の式番号（(28)）、引用された入力はそのまま残す。引用された入力は引用符を残す。

## 却下された式


## 却下された、またはないステップの自作の制御則


## ステップの自作の制御則の判定

law-designed =
    あなたのステップ{ $step }は設計どおりのダイナミクス { $designed } を与えます{ $own ->
        [yes] （あなた自身の{ $before }を用いた場合）：あなたの{ $output }は、それを与える{ $output }と、無作為に抽出した{ $draws }個の状態とパラメータ値で、大きさに対する相対差{ $worst }以内で一致します。
       *[no] ：あなたの{ $output }は論文の{ $output }と、無作為に抽出した{ $draws }個の状態とパラメータ値で、大きさに対する相対差{ $worst }以内で一致します。
    }{ $caveats }
law-not-designed =
    あなたのステップ{ $step }は設計どおりのダイナミクス { $designed } を与えません{ $own ->
        [yes] （あなた自身の{ $before }を用いた場合）：あなたの{ $output }（{ $unit }）は、それを与える{ $output }と、無作為に抽出した{ $draws }個の状態で、大きさに対する相対差で最大{ $worst }異なります。
       *[no] ：あなたの{ $output }（{ $unit }）は論文の{ $output }と、無作為に抽出した{ $draws }個の状態で、大きさに対する相対差で最大{ $worst }異なります。
    }{ $difference }{ $caveats }
law-not-designed-because = あなたのステップ{ $step }は設計どおりのダイナミクス { $designed } を与えません：{ $cause }。
law-cannot-judge = あなたのステップ{ $step }は判定できません：{ $cause }。
law-difference = 違い：{ $finding }。
law-difference-unnamed = 違いは論文の制御則の一つの項ではありません：あなたの制御則を、そのステップの導出と項ごとに比べてください。

## 判定の文の後に加える注記（いずれも文の後の空白で始まる）

law-caveat-none = {""}
law-caveat-unchained = {" "}あなたの{ $before }は{ $names }を読みますが、ループにはその変化率がありません（後のステップが選ぶ電圧か、ループにない導関数を含むためです）。そのため、このステップは論文の{ $before }で判定しています。
law-caveat-failed = {" "}あなたの{ $before }は、抽出した{ $draws }個の状態のうち{ $failed }個で有限の値を与えません。このステップはそれらの状態では判定していません。
law-caveat-both = { $unread }{ $failing }

## 設計どおりのダイナミクスからの隔たりが数値にならない理由


## 誤った制御則の誤り

law-term = 項 { $term }
law-term-part = 項 { $term } のうちの部分 { $part }
law-term-missing = 論文の制御則の{ $label }がありません
law-term-wrong-sign = { $label }の符号が逆です
law-term-twice = { $label }が二重に入っています
law-term-scaled = { $label }が本来の{ $factor }倍になっています
law-scenario-values-only = このシナリオのパラメータ値とゲインでのみ論文の制御則と一致します：制御則に名前が必要なところで、パラメータかゲインが数値で書かれています
law-rate-of-z =
    論文の制御則{ $sign ->
        [minus] から { $gain }·{ $z } を引いたもの
       *[plus] に { $gain }·{ $z } を加えたもの
    }です：このシナリオのパラメータでは、あなたの{ $z }は{ $meant } /sではなく{ $now } /sで減衰します。{ $z }の項のゲインと符号を確認してください

## 学生によくある誤り（制御則がそれと一致するときに名前を挙げる）

law-mistake-k1 = (28)では k1s1 = k1 − a3 であるところが k1 になっています
law-mistake-a3-x1h = (27)では a3·ω_d であるところが a3·x̂1 になっています
law-mistake-k2 = (36)では k2s1 = k2 − a7 − a8 であるところが k2 になっています：そのため ż2 の −(a7 + a8)·z2 が残ります
law-mistake-printed-dv1 = (31)に印刷されたとおりの v̇1 を、二つの誤植ごと使っています：a3·ω_d の微分は a3·ω̇_d なのに a3·ω_d のまま、â2 の微分はその変化率（既知の負荷では0）なのに â2 のままです
law-mistake-printed-dv1-wd = (31)に印刷されたとおりの v̇1 を使っています：a3·ω_d の微分は a3·ω̇_d なのに a3·ω_d のままです
law-mistake-printed-dv1-a2 = (31)に印刷されたとおりの v̇1 を使っています：â2 の微分はその変化率（既知の負荷では0）なのに â2 のままです
law-mistake-robust-2 = (38)のロバスト項 −h2²/(4·ε2)·z2 をスイッチ robust なしで書いているため、ロバスト項がオフのときにも働きます
law-mistake-psi-modulus = ψ_d を磁束の大きさ（ψ_d²）として扱っています：論文の z3 = x̂4² + x̂5² − ψ_d では、ψ_d は大きさの二乗です
law-mistake-factor-2 = ψ3 全体で係数2が抜けています：x̂4² + x̂5² の変化率は 2·(x̂4·x̂̇4 + x̂5·x̂̇5) です
law-mistake-residual-rates = ψ4 の、残差の連鎖律による項 2·(l41·x̂4 + l51·x̂5)·ẋ̃2 と 2·(l42·x̂4 + l52·x̂5)·ẋ̃3 が抜けています
law-mistake-drifts = ψ4 ではオブザーバの変化率 x̂̇4 = f̂4 + si4 と x̂̇5 = f̂5 + si5 であるところが、モデルのドリフト f̂4、f̂5 になっています：注入項が抜けています
law-mistake-drift-4 = ψ4 ではオブザーバの変化率 x̂̇4 = f̂4 + si4 であるところが、モデルのドリフト f̂4 になっています：注入項 si4 が抜けています
law-mistake-drift-5 = ψ4 ではオブザーバの変化率 x̂̇5 = f̂5 + si5 であるところが、モデルのドリフト f̂5 になっています：注入項 si5 が抜けています
law-mistake-factor-si4 = x̂̇4 の係数から si4 が抜けています：ψ3 の 2·x̂4·si4 の変化率からは 2·si4·x̂̇4 が出ます
law-mistake-factor-si5 = x̂̇5 の係数から si5 が抜けています：ψ3 の 2·x̂5·si5 の変化率からは 2·si5·x̂̇5 が出ます
law-mistake-robust-4 = (53)のロバスト項 −h4²/(4·ε4)·z4 をスイッチ robust なしで書いているため、ロバスト項がオフのときにも働きます

## 制御則で使える名前の意味（名前、記号、単位はその横に表示される）

formula-name-x1h = 推定回転子速度 ω̂（事後推定値 x̂1）
formula-name-x2h = 推定固定子電流 î_sa
formula-name-x3h = 推定固定子電流 î_sb
formula-name-x4h = 推定回転子磁束 φ̂_ra
formula-name-x5h = 推定回転子磁束 φ̂_rb
formula-name-x2 = 固定子電流の測定値 i_sa
formula-name-x3 = 固定子電流の測定値 i_sb
formula-name-xt2 = 残差 x̃2 = x2 − x̂2
formula-name-xt3 = 残差 x̃3 = x3 − x̂3
formula-name-dxt2 = x̃2 の公称の変化率：−(a7 + l21)·x̃2 − l22·x̃3
formula-name-dxt3 = x̃3 の公称の変化率：−l31·x̃2 − (a7 + l32)·x̃3
formula-name-dx4h = オブザーバによる x̂4 の変化率：−a8·x̂4 − a9·x̂1·x̂5 + a10·x̂2 + si4
formula-name-dx5h = オブザーバによる x̂5 の変化率：−a8·x̂5 + a9·x̂1·x̂4 + a10·x̂3 + si5
formula-name-wd = 速度指令値 ω_d
formula-name-dwd = その一階微分
formula-name-ddwd = その二階微分
formula-name-psi-d = x̂4² + x̂5² の磁束目標値
formula-name-si1 = x̂1 へのオブザーバの注入項：l11·x̃2 + l12·x̃3
formula-name-si2 = x̂2 へのオブザーバの注入項
formula-name-si3 = x̂3 へのオブザーバの注入項
formula-name-si4 = x̂4 へのオブザーバの注入項
formula-name-si5 = x̂5 へのオブザーバの注入項
formula-name-l11 = オブザーバゲイン L = K/Ts、第1行第1列
formula-name-l12 = オブザーバゲイン、第1行第2列
formula-name-l21 = オブザーバゲイン、第2行第1列
formula-name-l22 = オブザーバゲイン、第2行第2列
formula-name-l31 = オブザーバゲイン、第3行第1列
formula-name-l32 = オブザーバゲイン、第3行第2列
formula-name-l41 = オブザーバゲイン、第4行第1列
formula-name-l42 = オブザーバゲイン、第4行第2列
formula-name-l51 = オブザーバゲイン、第5行第1列
formula-name-l52 = オブザーバゲイン、第5行第2列
formula-name-a1 = μ = 3·np·M/(2·J·Lr)：a1·(x3·x̂4 − x2·x̂5) はトルクをJで割ったもの
formula-name-a2 = T0/J（EKFが負荷を推定するときは推定値 â2）
formula-name-a3 = Cf/J
formula-name-a5 = α·β（α = Rr/Lr、β = M/(σ·Lr)）
formula-name-a6 = np·β
formula-name-a7 = γ = Rs/σ + α·β·M
formula-name-a8 = α = Rr/Lr
formula-name-a9 = np
formula-name-a10 = α·M
formula-name-b = 1/σ
formula-name-da2 = EKFが負荷を推定するときは â2 の変化率（その注入項）、それ以外は0
formula-name-k1 = 速度誤差の減衰率
formula-name-k2 = トルク誤差の減衰率（k2 = a7 + a8 + k2s1）
formula-name-k3 = 磁束誤差の減衰率
formula-name-k4 = 磁束変化率誤差の減衰率
formula-name-k1s1 = k1 − a3
formula-name-k2s1 = k2 − a7 − a8
formula-name-h2 = (38)の |d̃2| の上界
formula-name-eps2 = (38)の ε2
formula-name-h4 = (53)の |d̃4| の上界
formula-name-eps4 = (53)の ε4
formula-name-robust = ロバスト項 (38) と (53) がオンのとき1、それ以外は0
formula-name-z1 = 速度誤差 x̂1 − ω_d
formula-name-z3 = 磁束誤差 x̂4² + x̂5² − ψ_d
formula-name-v1 = ステップ1の仮想入力（自作した場合はあなたのもの）
formula-name-z2 = トルク誤差 a1·(x3·x̂4 − x2·x̂5) − v1
formula-name-v3 = ステップ3の仮想入力（自作した場合はあなたのもの）
formula-name-z4 = 磁束変化率誤差 2·a10·(x2·x̂4 + x3·x̂5) − v3

## 制御則で呼べる関数：引数を付けた書き方と、返す値（関数名と引数はそのまま残す）

formula-function-sqrt = sqrt(x)：平方根
formula-function-exp = exp(x)：指数関数
formula-function-ln = ln(x)：自然対数
formula-function-sin = sin(x)：正弦、x は rad
formula-function-cos = cos(x)：余弦、x は rad
formula-function-tanh = tanh(x)：双曲線正接
formula-function-abs = abs(x)：絶対値
formula-function-sign = sign(x)：−1、0、1 のいずれか
formula-function-atan2 = atan2(y, x)：(x, y) の角度（rad）
formula-function-min = min(a, b)：小さい方
formula-function-max = max(a, b)：大きい方
formula-function-sat = sat(x, m)：x を [−m, m] に制限した値
