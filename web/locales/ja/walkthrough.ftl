# 設計解説（web/teaching/walkthrough*.js）：各節のタイトル、本文、注記、図、プロットのタイトルと信号の
# ラベル、各ステップの自作の制御則、安定性の報告、EKFの予測器の比較。
# 中括弧の文字（u_{"{"}k−1{"}"} など）は {"{"} と {"}"} と書く。

## Section model (walkthrough-text.js): 1. The motor model (2)

walkthrough-model-title = 1. 電動機モデル (2)
walkthrough-model-prose-1 = 状態は、静止a–b座標系における回転子速度 ω = x1、固定子電流 i_sa, i_sb = x2, x3、および回転子磁束 φ_ra, φ_rb = x4, x5 である。測定されるのは電流だけであり、電圧 u1, u2 が入力である。
walkthrough-model-prose-2 = 慣性モーメントで割ったトルクは a1(x3·x4 − x2·x5)（単位はrad/s²）であり、電流と磁束の外積である（a1 = 3n_pM/(2JL_r) はすでに 1/J を含んでいるので、N m で表すにはJを掛ける）。負荷 a2 + a3·x1 は、一定値T0と摩擦 Cf·ω をJで割ったものである。下の集約パラメータは、使用中の電動機パラメータからコアが計算する。プラント（シミュレーション上の電動機）とモデル（EKFと制御器が想定するもの）は異なっていてよい。
walkthrough-model-note = ここでのσの単位はヘンリーである。論文の σ = L_s − M²/L_r は固定子から見た全漏れインダクタンス（過渡インダクタンス）であり、固定子自身の漏れインダクタンス L_s − M ではない。多くの教科書は代わりに無次元の σ = 1 − M²/(L_sL_r) を用いる。
walkthrough-model-plot-title = 速度と磁束

## Section ekf (walkthrough-text.js): 2. The extended Kalman filter (10)–(20)

walkthrough-ekf-title = 2. 拡張カルマンフィルタ (10)–(20)
walkthrough-ekf-prose-1 = EKFは、測定された電流と印加された電圧から、五つの状態すべてを推定する。前進オイラー法で離散化したモデル (10) で予測し、ヤコビ行列 (11) で線形化し、イノベーション、すなわち測定された電流から予測された電流を引いたもので補正する。
walkthrough-ekf-prose-2 = Q（プロセスノイズ：すべての状態に q·Ts、さらに速度だけに q_speed·Ts）はモデルをどれだけ信頼するかを表し、R（測定ノイズ、r_std²·I）はセンサをどれだけ信頼するかを表す。単位の異なる状態に一つのqを用いるのは論文の選択である。q_speedを用いると、他の状態を緩めることなく速度推定値だけを動きやすくできる。ゲイン K_k は、一般形 (4) のオブザーバゲイン L = K_k/Ts として制御器に入る。制御器が許容しなければならないのは、推定誤差 x̃ である。
walkthrough-ekf-prose-3 = 整合したフィルタでは、イノベーションはおよそ95 %の時間で±2σ帯の内側にあり、正規化イノベーション二乗（NIS）の平均は2になる。この設計解説の範囲と上下限は、{ $wt-ekf-euler-nis--draws }通りのノイズ系列（シード1～{ $wt-ekf-euler-nis--draws }）にわたるものである。オイラー予測器は200 Hzの電流に追従できない。sine200では、その平均NISはどの系列でも{ $wt-ekf-euler-nis }以上であり、RK4予測器では高々{ $wt-ekf-rk4-nis }である。下で両者を比較する。
walkthrough-ekf-prose-4 = 論文の3.1節は、実装はしていない対策を一つ挙げている。ゆっくり変化する量を追加の状態として扱うことである。つまみ ekf.load は a2 = T_L0/J をランダムウォークとして追加する（このとき制御器は â2 とその変化率、すなわち注入項 l_a·(x̃2, x̃3) を用いる）。ekf.rr は回転子抵抗を追加する（制御器の a5, a7, a8, a10 は R̂_r に従う）。最後の二つのプロットは、両方の推定値を、Pから求めた±2σ帯とともに真値と比べて示す。追加の状態は、正しいか誤っているかにかかわらず、モデルに欠けているものを何でも吸収する。未知の負荷のもとでは、回転子抵抗の状態は負荷を抵抗と取り違える（レッスンを参照）。
walkthrough-ekf-note = 印刷された (13) は u_{"{"}k|k−1{"}"} で予測しているが、直前のサンプルのあいだに作用した電圧は u_{"{"}k−1{"}"} であり、(10) はこれを用い、ここでのフィルタもこれを用いる。ジョセフ形式は共分散の更新 (19) を二つの対称な項の和として書き、各項は任意のゲインKについて半正定値である。そのため短い形式 (I − K_kC)P_{"{"}k|k−1{"}"} に比べて、丸め誤差によってPがこれらの性質のいずれかを失うことははるかに起こりにくい。ただし、それが保証されるわけではない。
walkthrough-ekf-plot-title = イノベーション ỹ_a と、S_k から求めた±2σ帯
walkthrough-ekf-plot4-title = 正規化イノベーション二乗とその95 %帯（χ²、自由度2）
walkthrough-ekf-plot2-title = 速度推定値とその分散
walkthrough-ekf-plot3-title = 磁束の大きさ：真値と推定値
walkthrough-ekf-plot5-title = 負荷トルク：±2σ帯付きの推定値 â2·J と真値
walkthrough-ekf-plot6-title = 回転子抵抗：±2σ帯付きの推定値と電動機の値

## Section bridge (walkthrough-text.js): 3. From the observer to the controller: (4) and (5)

walkthrough-bridge-title = 3. オブザーバから制御器へ：(4) と (5)
walkthrough-bridge-prose-1 = 制御器には電動機の状態は見えない。見えるのはオブザーバの推定値 x̂ と、測定された電流 x2, x3 だけである。推定誤差を x̃ = x − x̂ と書く。その成分のうち二つは測定される。電流の残差 x̃2 = x2 − x̂2 と x̃3 = x3 − x̂3 である。三つは測定されない。速度誤差 x̃1 と、磁束誤差 x̃4, x̃5 である。
walkthrough-bridge-prose-2 = 論文は、一般形 (4) のオブザーバに対して制御器を設計する。これはモデル (2) を推定値で書き写し、注入項 si_i = l_i1·x̃2 + l_i2·x̃3 (5) を加えたものである。注入項は、測定された残差によって各推定値を引き寄せる補正である。前進オイラー法の一ステップとして読めば、EKFの更新は、L = K_k/Ts と事前残差 y_k − Cx̂_{"{"}k|k−1{"}"} (15) を用いて、第2行から第5行でこの形をもつ。第1行はほぼこの形であるにすぎない。(4) が測定された x2, x3 を読むところで、EKFのトルク項は推定された電流 x̂2, x̂3 を読むからである。ここでの制御器は事後残差 y_k − Cx̂_{"{"}k|k{"}"} = (I − CK_k)(y_k − Cx̂_{"{"}k|k−1{"}"}) を用いる。これは、制御器が用いる事後推定値 x̂_{"{"}k|k{"}"} に対する x̃ = x − x̂ に合う。両者が一致するのは、CK_k が小さいあいだだけである。
walkthrough-bridge-prose-3 = (2) から (4) を引くと、下の誤差の動特性が得られる。制御器は測定された残差を微分する（残差はv1とψ3に含まれる）。そしてその導関数は、測定されない x̃1, x̃4, x̃5 を含む。そのような導関数はそれぞれ二つに分けられる。一つは公称の残差の動特性、すなわち x̃1 = x̃4 = x̃5 = 0 のときに ẋ̃2 と ẋ̃3 がとる値であり、制御器はこれを計算する。もう一つは残りの部分であり、制御器はこれを計算できない。また、設計ではLを定数とみなす。以下ではどこでも L̇ を無視する。
walkthrough-bridge-prose-4 = これが、論文の題名にある統合設計である。オブザーバの誤差の動特性は制御器の設計の内部にあり、未知の項は、測定された電流または残差が微分されるところ、すなわちステップ2（ż2 は ẋ2, ẋ3 と v̇1 を含む）とステップ4（ż4 は注入項 si4, si5 の変化率を含む）にだけ現れる。ステップ1と3には未知の項はない。未知の項は d̃2 と d̃4 にまとめられ、有界な外乱として扱われる。モデルが正確なら、未知の項はこれですべてである。電動機と異なるモデルは、ż2 と ż4 に独自の項を加えるが、それは論文の d̃2 と d̃4 には含まれていない。
walkthrough-bridge-prose-5 = 統合設計が置き換えるのは、論文の要旨が挙げている時間スケールの分離、すなわちオブザーバを制御器よりはるかに速くして、制御器がその推定値を状態とみなしてよいようにすることである。以下の制御則も、状態フィードバック則ならxを置くところにx̂を置いており、これは確実等価性の形である。この設計が新たに加えるのは、推定誤差を無視するのではなく、仮定4.2のもとで有界な d̃2 と d̃4 として、リアプノフ関数による議論に組み込むことである。
walkthrough-bridge-figure = 制御器とオブザーバ（論文の図1と同様）。制御器が電動機を見るのは、EKFの推定値、ゲイン、残差と、測定された電流を通してだけである。
    .alt = ブロック線図：指令値と、EKFの推定値、ゲイン、残差がバックステッピング制御器に入る。制御器の電圧は電圧制限を通って電動機を駆動する。測定された電流と印加された電圧はEKFに戻る。
walkthrough-bridge-note = 論文は注入項を si_i(x̃2, x̃3) と書く。ここでの si_i はその値 l_i1·x̃2 + l_i2·x̃3 である。文字ψは、磁束の目標値 ψ_d と、以下のステップの既知の項 ψ2, ψ3, ψ4 の両方を表すが、両者は無関係である。

## Section step1 (walkthrough-text.js, walkthrough-laws.js): 4. Step 1: the speed loop

walkthrough-step1-title = 4. ステップ1：速度ループ
walkthrough-step1-prose-1 = ステップ1は推定速度を制御する：z1 = x̂1 − ω_d。その導関数は、(4) の最初の式から得られる開ループ (23) である。摩擦項を指令値のまわりで −a3·x̂1 = −a3·z1 − a3·ω_d と分けると、電動機自身の減衰 −a3·z1 は残り、−a3·ω_d は既知の項となる。
walkthrough-step1-prose-2 = 仮想入力とは、電動機にはそのような入力がないにもかかわらず、あるステップが自身の入力として扱う信号である。ステップ1の仮想入力は、測定された電流と推定された磁束から作られるトルク項 a1(x3·x̂4 − x2·x̂5) である。これがv1（慣性モーメントで割ったトルク、rad/s²）に等しくなるよう求め、その不足分をz2と名づける (24)。このとき (25) が成り立つ。
walkthrough-step1-prose-3 = v1 = v1a + v1s と選ぶ (26)。フィードフォワード v1a (27) は既知の項をすべて打ち消す。si1は、測定された残差だけを用いるので既知である。フィードバック v1s = −k1s1·z1 (28) により (29)、すなわち ż1 = −k1·z1 + z2（k1 = a3 + k1s1）が残る。k1s1は、減衰率k1のうち、電動機自身の減衰a3に制御器が上乗せする部分である。そのため v1a には a3·x̂1 ではなく a3·ω_d が含まれる。ステップ1と2は電動機自身の減衰を残し、ステップ3と4は既知のものをすべて打ち消す。
walkthrough-step1-prose-4 = ステップ1のリアプノフ関数は V1 = ½z1² である。(29) に沿って V̇1 = z1ż1 = −k1z1² + z1z2 であり、交差項 z1z2 を除けば負である。この交差項はステップ2が打ち消す。
walkthrough-step1-prose-5 = ステップ2には v̇1 が必要である。Lを一定として（L̇ を無視して）(30) を微分する。注入項の変化率は l11·ẋ̃2 + l12·ẋ̃3 であり、ẋ̃2, ẋ̃3 は測定されない x̃1, x̃4, x̃5 を含む（第3節）。v̇1 の既知の部分では、これらの代わりに公称の残差の動特性を用いる。残り、すなわち下の「…」は d̃2 に入る。
walkthrough-step1-note = 印刷された (31) では、a3·ω̇_d と dâ2/dt であるべきところが a3·ω_d と â2 になっている（上では訂正済み）。「…」は x̃1, x̃4, x̃5 の項であり、−(l11·a5 − l12·a6·x̂1)·x̃4 − (l12·a5 + l11·a6·x̂1)·x̃5 − (l11·a6·x5 − l12·a6·x4)·x̃1 である。
walkthrough-step1-plot-title = ステップ1：z1、v1 = v1a + v1s とトルク項
walkthrough-step1-plot3-title = ステップ1：実行で得られた ż1（各サンプルでの変化をTsで割ったもの）と、設計した −k1·z1 + z2 の比較
walkthrough-law-1-intro = v1を自分で導出し、この節の名前（x̂1 は x1h、ω_d と ω̇_d は wd と dwd、si1、a2、a3、k1s1、z1。一覧は下にある）を用いた式として、+ − * / ^、括弧、関数で下に書く。Enterを押すか入力を止めるとすぐに、論文の (26) の代わりに20 kHzで実行される。欄を空にすると論文の制御則に戻る。実行の後、判定は、無作為に選んだ状態とパラメータの値において、自分の制御則が設計した動特性 ż1 = −k1·z1 + z2 を与えるかを調べる。下のプロットは実行全体にわたるその残差を示す。この動特性を与える制御則なら、残差はゼロである。
walkthrough-law-1-plot-title = ステップ1：自分の制御則の残差、ż1 と設計した ż1 = −k1·z1 + z2 の比較（自分のv1から論文のものを引いたもの）

## Section step2 (walkthrough-text.js, walkthrough-laws.js): 5. Step 2: the torque loop

walkthrough-step2-title = 5. ステップ2：トルクループ
walkthrough-step2-prose-1 = ステップ2は、z2をゼロに駆動することで、トルク項をv1に追従させる。ここで初めて電圧が現れる。(24) を微分すると、ẋ2 と ẋ3 が bu1 と bu2 をもたらすので、v2 = b·a1(x̂4·u2 − x̂5·u1) が入力となる。x̂̇4, x̂̇5 は (4) のものであり、−v̇1 は (31) である。制御器が知っているものをψ2にまとめ、トルク項を z2 + v1 と書くと、(32) が得られる。
walkthrough-step2-prose-2 = ψ2は既知のものすべてをまとめたものである。磁束と電流の動特性、注入項 si4, si5、および v̇1 の既知の部分である。測定されない誤差 x̃1, x̃4, x̃5 は d̃2 (33) を通してだけ入る（モデルが正確な場合。電動機と異なるモデルは ż2 に独自の項を加える）。この項はこれらについて線形であり、係数は x̂、x、L から作られるので、x̂、x、L、x̃ が有界であるあいだは有界である。論文は射影 (7)–(9) によって x̂ を有界に保つ。これが有界にするのは x̃ ではなく x̂ であり、射影が作用しているあいだ x̂̇ はもはや (4) ではなく、ψ2–ψ4 も厳密ではない。ここでのEKFには射影がない。x̂ を有界に保つものは、実行そのもの以外にない。
walkthrough-step2-prose-3 = v2 = v2a + v2s と選ぶ (34)。v2a = −ψ2 − z1 は、既知の項と、V̇1 の交差項 z1z2 を打ち消す。v2s = −k2s1·z2 + v2s2 (36) はフィードバックを加える。電動機自身が減衰 a7 + a8 をもたらすので、k2 = a7 + a8 + k2s1 である。論文の電動機では a7 + a8 = 232.7 /s なので、k2 = 1200 /s のとき k2s1 = 967.3 /s である。
walkthrough-step2-prose-4 = ロバスト項 v2s2 = −h2²z2/(4ε2) (38) は、h2が|d̃2|の上界であればd̃2を支配する。V_s2 = ½(z1² + z2²) (39) とすると、V̇_s2 = −k1z1² − k2z2² + z2(v2s2 + d̃2) ≤ −k1z1² − k2z2² + ε2 (40) となる。際限なく大きくなるd̃2に対しては、どんな有限のh2でもこれは成り立たない。|d̃2|がh2を超えると、z2(v2s2 + d̃2) はε2を超えうる。
walkthrough-step2-prose-5 = どの項をd̃2に入れるかは選択の問題である。(33) は真の速度を x1 = x̂1 + x̃1 と書き、x̂1 の部分をψ2に残している。別の分け方をすれば、項がψ2とd̃2のあいだで移るだけで、ż2 は変わらない。ここで論文が頼っているのは仮定4.2 (22) である。この仮定は、x̃ が既知の箱 [x̃_min, x̃_max] の中にあるとし、そのときd̃2は有界であると述べ、h2をその上界とする (38)。ステップ4がh4を定める (53) のと同様である。箱や上界の値は与えられていない。ここではh2とh4は設定項目である。下のd̃2のプロットとステップ4のd̃4のプロットは、表示中の実行におけるこれらの項を測定しており、その実行に対してそれらの大きさを決める一つの方法となる。そのうえでε2は、(59) の終局値 ε/λ と、v2s2 がz2の減衰率に加える率 h2²/(4ε2) とのトレードオフを決める。また、周期Tsでサンプリングされるループが保てる減衰率は、およそ 2/Ts よりかなり小さいものに限られる。レッスン「ロバスト項と上界 (59)」で、一つの選び方を具体的に検討している。
walkthrough-step2-prose-6 = z2を微分すると、電動機自身の減衰 −(a7 + a8)·z2 も現れる。印刷された (32) はこれを落としており、(36) の k2 = a7 + a8 + k2s1 はこれを勘定に入れている。
walkthrough-step2-note = 印刷された (35) は v2a = −ψ2 − d̃2 − z1 である。d̃2は未知なので、どんな制御器もこれを差し引くことはできない。ここでの制御器は −ψ2 − z1 を用い、d̃2はロバスト項に任せる。
walkthrough-step2-shows-1 = 下のプロットは、シミュレーション上の真値からd̃2を評価したものである。すなわち電動機の実際の ż2 から制御器が知っている項を引いたもので、測定された電流の代わりに真の電流を用いる。これは遅延補償なしの五状態のEKFについて評価される。追加の状態をもつオブザーバ（ekf.load、ekf.rr）や delay.comp を用いる場合、プロットは空のままである。(38) が|d̃2|を支配するには、h2は少なくともそのピーク値でなければならない。まず正確なモデルのstepで読み、次にモデル誤差（plant.j、plant.rr）を与えて読む。電動機のR_rがモデルより10 %大きい（plant.rr = 5.445）と、ループは{ $wt-rrhigh-runaway--draws }系列中{ $wt-rrhigh-runaway }系列で暴走するか破綻する。磁束が逸脱するのが{ $wt-rrhigh-off }系列、制御器が終了前に破綻するのが{ $wt-rrhigh-fail }系列である。プリセットの0.1 sの終わりで磁束は{ $wt-rrhigh-flux-min }～{ $wt-rrhigh-flux-max } Wbであり、1 s後には{ $wt-rrhigh1s-flux-min }～{ $wt-rrhigh1s-flux-max } Wbとなる。そして (33) のd̃2の係数はxとともに大きくなる。
walkthrough-step2-plot-title = ステップ2：z2 と v2 = v2a + v2s
walkthrough-step2-plot2-title = ステップ2：シミュレーション上の真値から評価したd̃2と±h2
walkthrough-step2-plot3-title = ステップ2：実行で得られた ż2（各サンプルでの変化をTsで割ったもの）と、設計した −k2·z2 − z1（robust=1のときはロバスト項を含む）の比較
walkthrough-law-2-intro = v2を自分で導出し、この節の名前（v1とz2（ステップ1から）、x2とx3、x4hとx5h、si4とsi5、dxt2とdxt3、l11とl12、ddwd、a1～a10、k1、k1s1、k2s1。一覧は下にある）を用いた式として、+ − * / ^、括弧、関数で下に書く。Enterを押すか入力を止めるとすぐに、論文の (34) の代わりに20 kHzで実行される。欄を空にすると論文の制御則に戻る。ステップ1で自分のv1を用いている場合、自分のv2はそれにもとづいて判定される。つまり、自分のv1を、それが与えるż1とともに微分したものでなければならない。実行の後、判定は、無作為に選んだ状態とパラメータの値において、自分の制御則が設計した動特性 ż2 = −k2·z2 − z1 を与えるかを調べる。下のプロットは実行全体にわたるその残差を示す。この動特性を与える制御則なら、残差はゼロである。
walkthrough-law-2-plot-title = ステップ2：自分の制御則の残差、ż2 と設計した ż2 = −k2·z2 − z1 の比較（自分のv2から、それを与えるv2を引いたもの。論文のもの、または自分のv1を用いている場合はそれを微分したもの）

## Section step3 (walkthrough-text.js, walkthrough-laws.js): 6. Step 3: the flux outer loop

walkthrough-step3-title = 6. ステップ3：磁束の外側ループ
walkthrough-step3-prose-1 = ステップ3は推定磁束の大きさの二乗を制御する：z3 = x̂4² + x̂5² − ψ_d (42)。その導関数に必要なのは (4) だけである：ż3 = 2x̂4·x̂̇4 + 2x̂5·x̂̇5 − ψ̇_d。ここではa9の項が打ち消し合い、下では推定値だけで書かれている。x̂2 = x2 − x̃2、x̂3 = x3 − x̃3 と書くと、仮想入力 2a10(x2·x̂4 + x3·x̂5)、すなわち固定子電流が駆動するż3の部分が、ψ3 (43) から分離される。
walkthrough-step3-prose-2 = ψ3は推定値と測定された残差だけに依存するので、ステップ3には未知の項がまったくない。v3 = −ψ3 − k3·z3 (45) とすると、オブザーバ自身の磁束推定値について、連続時間で ż3 = −k3·z3 + z4 (46) が厳密に成り立つ。そのリアプノフ関数は V3 = ½z3² で、V̇3 = −k3z3² + z3z4 である。交差項はステップ4が打ち消す。
walkthrough-step3-prose-3 = v3 = −ψ3 − k3·z3 なので、次の誤差 z4 (44) は z4 = ż3 + k3·z3 である。これは、z3が減衰率k3で減衰しきれていない度合いを表す。
walkthrough-step3-prose-4 = 論文はフィードバックを v3s = −k3s1·z3 と書き、k3 = k3s1 とおく (46)。v3aは、磁束自身の減衰 −2a8·(x̂4² + x̂5²) も含めてψ3をすべて打ち消すので、減衰率k3はすべて制御器によるものである。これに対してステップ1では、電動機の減衰a3がk1の一部となっている。
walkthrough-step3-note = 問題設定は x4² + x5² がψ_d²に追従することを求めているが、(42) はψ_dを引いている。ここでのψ_dは大きさの二乗の目標値であり、単位はWb²である。シナリオの psi_d はこの目標値であり、psi_d = 0.5 Wb² は磁束の大きさ |φ| = 0.707 Wb を求めることになる。論文のシミュレーションは、所望の磁束の大きさとして「ϕ_d = 0.5」と述べており、文字どおりに読めば0.5 Wb（0.25 Wb²）である。プリセットはこれを、(42) の用い方に合わせて大きさの二乗とみなしている。これは論文の初期磁束 [0.5, 0.5] の大きさの二乗である。
walkthrough-step3-shows-1 = z3のプロットが示すのは、電動機の磁束ではなく、オブザーバ自身の磁束推定値の目標値に対する誤差である。正確なモデルのstepで、15 ms以降、そのRMSはEKFで{ $wt-z3-min }～{ $wt-z3-max } mWb²、測定ノイズなし（noise=0）で{ $wt-z3-quiet } mWb²である。ノイズはイノベーションを通してz3に入る。推定値が電動機の磁束そのものである理想オブザーバ（perfect=1）では、{ $wt-z3-perfect-max } mWb²未満にとどまる。
walkthrough-step3-plot-title = ステップ3：z3 と v3 = v3a + v3s
walkthrough-step3-plot3-title = ステップ3：実行で得られた ż3（各サンプルでの変化をTsで割ったもの）と、設計した −k3·z3 + z4 の比較
walkthrough-law-3-intro = v3を自分で導出し、この節の名前（x4hとx5h、xt2とxt3、si4とsi5、a8、a10、k3、z3。一覧は下にある）を用いた式として、+ − * / ^、括弧、関数で下に書く。Enterを押すか入力を止めるとすぐに、論文の (45) の代わりに20 kHzで実行される。欄を空にすると論文の制御則に戻る。実行の後、判定は、無作為に選んだ状態とパラメータの値において、自分の制御則が設計した動特性 ż3 = −k3·z3 + z4 を与えるかを調べる。下のプロットは実行全体にわたるその残差を示す。この動特性を与える制御則なら、残差はゼロである。
walkthrough-law-3-plot-title = ステップ3：自分の制御則の残差、ż3 と設計した ż3 = −k3·z3 + z4 の比較（自分のv3から論文のものを引いたもの）

## Section step4 (walkthrough-text.js, walkthrough-laws.js): 7. Step 4: the flux inner loop and the voltages

walkthrough-step4-title = 7. ステップ4：磁束の内側ループと電圧
walkthrough-step4-prose-1 = ステップ4はz4をゼロに駆動する。その入力 v4 = 2a10·b(x̂4·u1 + x̂5·u2) は、電圧の二つ目の組み合わせである。z4 = ż3 + k3·z3 なので、ż4 = z̈3 + k3·ż3 = z̈3 + k3(−k3z3 + z4) である。ż3 を、推定値だけで書いた形（ステップ3の最初の式）でもう一度微分する。形 (43) で微分してはならない。そこに含まれる測定された電流が、打ち消し合う未知の項をもたらすからである。x̂̇4, x̂̇5 の項は下のようにまとまり、x̂̇2 と x̂̇3 は電圧（v4）と電流の動特性をもたらし、注入項の変化率 l41·ẋ̃2 + l42·ẋ̃3 と l51·ẋ̃2 + l52·ẋ̃3 は残差の導関数をもたらす。
walkthrough-step4-prose-2 = 2a10·(x2·x̂4 + x3·x̂5) の導関数では、ẋ2 と ẋ3 (2) のa6の項は、既知の部分で打ち消し合う：a6·x̂1·(x̂4·x̂5 − x̂5·x̂4) = 0。ψ4にa6が含まれないのはこのためである。x̃1, x̃4, x̃5 を含む残りはd̃4に入る。V_s4 = ½z3² + ½z4² (56) とすると、V̇_s4 = −k3z3² − k4z4² + z4(v4s2 + d̃4) ≤ −λ4·V_s4 + ε4（λ4 = 2·min(k3, k4)）となり、これを積分すると (57) が得られる。第8節でVについて行うのと同じである。
walkthrough-step4-prose-3 = ψ4は、ẋ̃2 と ẋ̃3 に公称の残差の動特性（第3節）を用い、L̇ を無視している。印刷された (47) は L̇ = 0 のもとで成り立つ。公称の動特性が取りこぼすもの、すなわち 2(l41·x̂4 + l51·x̂5) と 2(l42·x̂4 + l52·x̂5) で重み付けされた、ẋ̃2 と ẋ̃3 の x̃1, x̃4, x̃5 の項が d̃4 である。
walkthrough-step4-prose-4 = v4 = −ψ4 − z3 − k4·z4 + v4s2 と選ぶ (49)–(51)。−z3 は V̇3 の交差項 z3z4 を打ち消し、(52) が得られる。v2 と v4 を合わせると、非干渉化行列 (54) を通して両方の電圧が定まる。この行列は、推定磁束がゼロでない限り正則である (55)。その後、電圧制限が作用する。論文が与えているのは400 Vという制限だけである。正方形の制限（vlimit=box）は各成分を±400 Vにクリップし、円と、インバータの六角形（vlimit）は、ベクトル全体をその向きを保ったまま縮小する。制限が作用しているあいだ、設計した誤差の動特性はもはや成り立たない。
walkthrough-step4-note = 印刷された (48) では、a41, a42 であるべきところが a21, a22 になっている（上では訂正済み）。上のψ4は、印刷された (47) を並べ替えたものである。論文は 2a10(x̂4·si2 + x̂5·si3) を 2a10(l21·x̃2·x̂4 + …) と書き、x̂̇4, x̂̇5 の積をそれぞれ二つに分けている。そのd̃4は、印刷されたものと項ごとに同じである。
walkthrough-step4-shows-1 = d̃2 と同様にシミュレーション上の真値から評価した|d̃4|を、下に±h4と比べてプロットする。(53) がこれを支配するには、h4は少なくともそのピーク値でなければならない。
walkthrough-step4-shows-2 = 最初の5 msのあいだ、起動過渡は制限をはるかに超える電圧を指令する。指令された u_sa のピーク値は、stepで{ $wt-cmd-step-min }～{ $wt-cmd-step-max } V、rr-mismatchで{ $wt-cmd-rr-min }～{ $wt-cmd-rr-max } Vであり、rr-mismatchでは{ $wt-clip-rr-min }～{ $wt-clip-rr-max } msまで制限が指令をクリップする。プロットは、この過渡の後の実行に合わせてy軸を調整する。過渡を見るには、プロットの上の「起動過渡の後にy軸を合わせる」のチェックを外す。
walkthrough-step4-plot-title = ステップ4：z4、v4、および制限前後の電圧
walkthrough-step4-plot2-title = ステップ4：シミュレーション上の真値から評価したd̃4と±h4
walkthrough-step4-plot3-title = ステップ4：実行で得られた ż4（各サンプルでの変化をTsで割ったもの）と、設計した −k4·z4 − z3（robust=1のときはロバスト項を含む）の比較
walkthrough-law-4-intro = v4を自分で導出し、この節の名前（v3とz4（ステップ3から）、dx4hとdx5h、dxt2とdxt3、si2～si5、l41～l52、a5、a7、a8、a10、k3、k4、z3。一覧は下にある）を用いた式として、+ − * / ^、括弧、関数で下に書く。Enterを押すか入力を止めるとすぐに、論文の (49) の代わりに20 kHzで実行される。欄を空にすると論文の制御則に戻る。ステップ3で自分のv3を用いている場合、自分のv4はそれにもとづいて判定される。つまり、自分のv3を、それが与えるż3とともに微分したものでなければならない。実行の後、判定は、無作為に選んだ状態とパラメータの値において、自分の制御則が設計した動特性 ż4 = −k4·z4 − z3 を与えるかを調べる。下のプロットは実行全体にわたるその残差を示す。この動特性を与える制御則なら、残差はゼロである。
walkthrough-law-4-plot-title = ステップ4：自分の制御則の残差、ż4 と設計した ż4 = −k4·z4 − z3 の比較（自分のv4から、それを与えるv4を引いたもの。論文のもの、または自分のv3を用いている場合はそれを微分したもの）

## Section stability (walkthrough-text.js): 8. Stability: Theorem 4.6

walkthrough-stability-title = 8. 安定性：定理4.6
walkthrough-stability-prose-1 = V = ½(z1² + z2² + z3² + z4²) (58) とすると、設計した四つの誤差の動特性から V̇ = −k1z1² − k2z2² − k3z3² − k4z4² + z2(v2s2 + d̃2) + z4(v4s2 + d̃4) (60) が得られる。交差項 ±z1z2 と ±z3z4 は打ち消し合う。v2a の −z1 と v4a の −z3 はそのためにある。
walkthrough-stability-prose-2 = 証明はあと三行で終わる。第一に、|d̃2| ≤ h2 ならば（h2 は (38) の δ_d2、すなわちd̃2の上界である。論文は、仮定4.2による x̃ の上下限 (22) のもとでこの上界が存在すると主張するが、導出はしていない。d̃2 は x̃1, x̃4, x̃5 について線形で、その係数は真の x1, x4, x5、推定値、およびゲイン l11, l12 を含む。したがって x̃ の上下限がこれを抑えるのは、これらが有界であるあいだに限られる）、ヤングの不等式により、ロバスト項の組は z2(v2s2 + d̃2) ≤ h2|z2| − h2²z2²/(4ε2) ≤ ε2 と抑えられる。差が完全平方だからである。z4 についても、h4 と ε4 で同じことが成り立つ。第二に、Σk_i·z_i² ≥ min(k_i)·Σz_i² = 2·min(k_i)·V = λV である。したがって V̇ ≤ −λV + ε（ε = ε2 + ε4）である。第三に、比較の段階である。e^(λt)·V の変化率は e^(λt)·(V̇ + λV) ≤ ε·e^(λt) であり、0からtまで積分すると (59) が得られる。
walkthrough-stability-prose-3 = Vは単位の異なる二乗を足し合わせており（z1 は rad/s、z2 は rad/s²、z3 は Wb²、z4 は Wb²/s）、ε2（rad²/s⁵）と ε4（Wb⁴/s³）の単位も異なる。(59) はSI単位での数値について成り立つ。そのままではあらゆる重み付けに移せるわけではない。V = ½Σw_i·z_i² とすると、V̇ の交差項は (w1 − w2)·z1z2 と (w3 − w4)·z3z4 となり、これらが打ち消し合うのは w1 = w2 かつ w3 = w4 のときだけである（重みが等しくなければ交差項が残り、λが下がる）。ただし、(35) の結合項 −z1 と (50) の結合項 −z3 を −(w1/w2)·z1 と −(w3/w4)·z3 にスケーリングし直せば別である。これらの結合項は、単なる和では見えない単位（SIで1/s²）をもつ。この上界が抑えるのは和であり、各 ½z_i² は和を通してしか抑えられない。プロットは、この実行について記録されたVをこの上界と比べる。
walkthrough-stability-prose-4 = 定理が抑えるのは推定値の誤差 z_i であって、電動機ではない。真の速度誤差は |x1 − ω_d| ≤ |z1| + |x̃1| である。定理は、実行全体にわたって |d̃2| ≤ h2 と |d̃4| ≤ h4 を仮定している。これらの上界自体が x、x̂、L の有界性を前提としているが、それは定理が結論として導くものである。また、無視された L̇ の項は、ψにもd̃にも含まれていない。仮定が成り立たないとき、定理は真の電動機について何も述べない。
walkthrough-stability-shows-1 = EKFの初期誤差が10 %で、モデルが正確な場合、電圧制限が起動を持ちこたえさせる。制限があると、sine200が暴走するのは{ $wt-limit-runaway--draws }系列中{ $wt-limit-runaway }系列である（電動機のR_rがモデルより10 %大きい場合は、制限があっても{ $wt-limit-rrhigh-runaway }系列）。しかし制限がないと（vmax=100000）{ $wt-nolimit-runaway }系列で暴走し、最大{ $wt-nolimit-off-max } rad/sずれ、磁束が最大{ $wt-nolimit-flux-max } Wbに達した状態で終わる。正しい初期推定値から始めると（init_err=0）、同じ実行は、制限がなくても、正確なモデルではどの系列でもRMS { $wt-exact-rms-min }～{ $wt-exact-rms-max } rad/sで追従する。電動機のR_rがモデルより10 %大きいと、それでも破綻する。RMS誤差は{ $wt-exact-rrhigh-rms } rad/s以上であり、{ $wt-exact-rrhigh-runaway--draws }系列中{ $wt-exact-rrhigh-runaway }系列で暴走する。
walkthrough-stability-plot-title = リアプノフ関数 V(t) = ½Σz_i² と上界 (59) の比較（対数目盛）

## The plots' signals, in their legends (walkthrough-text.js, walkthrough-laws.js)

walkthrough-series-estimated = { $signal } 推定値
walkthrough-series-true = { $signal } 真値
walkthrough-series-right = { $signal }（右軸）
walkthrough-series-right-unit = { $signal }（{ $unit }、右軸）
walkthrough-series-feedforward = { $term } フィードフォワード
walkthrough-series-feedback = { $term } フィードバック
walkthrough-series-run = { $signal }（実行）
walkthrough-series-designed = { $expression }（設計）
walkthrough-series-load-true = T_L 真値（T0 + ステップ）
walkthrough-series-rr-motor = 電動機のR_r
walkthrough-series-u-commanded = u_sa 指令 (V)
walkthrough-series-u-applied = u_sa 印加 (V)
walkthrough-series-lyapunov = V(t) リアプノフ関数
walkthrough-series-bound = 上界 (59)
walkthrough-series-law-paper = 自分の{ $output } − 論文の{ $output }
walkthrough-series-law-gives = 自分の{ $output } − { $rate }を与える{ $output }
walkthrough-nis-low = 2.5 %分位点
walkthrough-nis-high = 97.5 %分位点
walkthrough-stability-plot-unit = V（混合単位：½Σz_i²）

## A section's frame (walkthrough-sections.js, walkthrough.js)

walkthrough-diagram-label = 節「{ $section }」の図
walkthrough-equation-label = 節「{ $section }」の式{ $number }
walkthrough-run-shows = この実行が示すこと
walkthrough-lumped-label = プラントとモデルの集約パラメータ
walkthrough-lumped-plant = プラント
walkthrough-lumped-model = モデル
walkthrough-stability-waiting = シナリオを実行すると、Vを上界と比較します。
walkthrough-compare-button = オイラー予測器とRK4予測器を比較（このシナリオで）
walkthrough-compare-label = オイラー予測器とRK4予測器の比較
walkthrough-knobs = 設計のつまみ
walkthrough-ifoc-note = このシナリオは、古典的な比較基準であるIFOCを実行している。以下のバックステッピングの項は、比較のためにEKFの推定値から評価したものであり、電動機を駆動しているのはこれらではない。
walkthrough-equations-failed = 式を読み込めませんでした。接続を確認して、設計解説を開き直してください。

## The stability report (walkthrough-reports.js): the bound (59) against V over the run, then
## what it adds when V leaves the bound, by the likely cause. Its sentences are shown one after
## the other, parted by a space.

walkthrough-stability-nothing = 何も記録されていない。
walkthrough-stability-bound-robust = λ = 2·min(k) = { $lambda } 1/s、ε = { $eps }（ロバスト項あり）。
walkthrough-stability-bound-off = λ = 2·min(k) = { $lambda } 1/s、ε = { $eps }（ロバスト項なし。したがって上界は V(0)·e^(−λt)）。
walkthrough-stability-under =
    Vは{ $samples ->
       *[other] 全{ $samples }サンプル
    }で上界の下にとどまっている。
walkthrough-stability-above =
    Vは{ $samples ->
       *[other] { $samples }サンプル
    }中{ $outside }サンプルで上界を上回っており、最初は t = { $first } s である。そのうち{ $outsideSaturated }サンプルでは電圧が飽和している（飽和しているサンプルは全体で{ $saturated ->
       *[other] { $saturated }サンプル
    }）。
walkthrough-stability-cause-saturation = それらのサンプルの大部分では、指令電圧が制限を超えている。飽和は、上界が前提とする設計した誤差の動特性を崩す。
walkthrough-stability-cause-sampling = 理想オブザーバと正確なモデルでは d̃2 = d̃4 = 0 であり、連続時間ならVは上界の下にとどまる（ゲインが等しければ上界の上に乗る）。サンプル値ループは、z_i にTs程度の独自の誤差を残す。decayでは、上界が下がり続けるあいだVはある下限で止まるので、Vは上界をはるかに上回って終わる。Tsを半分にすると、この下限は{ $wt-decay-halfts }倍になる。回転子抵抗の誤差は、この下限をはるかに超える独自の外乱を加える。電動機のR_rがモデルより10 %大きい場合と小さい場合、decayでVが終わる値は、それぞれこの下限の{ $wt-decay-rrhigh }倍と{ $wt-decay-rrlow }倍である。慣性モーメントの誤差は、decayではそうならない。モデルの慣性モーメントが電動機より20 %大きい場合と小さい場合（model.j = 0.024 と model.j = 0.016）、Vが終わる値はそれぞれこの下限の{ $wt-decay-jhigh }倍と{ $wt-decay-jlow }倍である。
walkthrough-stability-cause-estimation-errors = 推定誤差は d̃2 と d̃4 として入る。ロバスト項がないと、z2·d̃2 + z4·d̃4 を抑えるものは何もないので、上界（このとき d̃ = 0 を仮定している）は成り立つとは限らない。
walkthrough-stability-cause-eps-or-sampling = εが実際の d̃2, d̃4 に対して小さすぎるか、20 kHzのサンプリングが、連続時間の証明にはない誤差を加えている。

## The EKF's predictors compared (walkthrough-reports.js)

walkthrough-compare-note = シナリオとシードは同じで、EKFの予測器だけが異なる。指標は、指標欄と同じく、起動過渡の終わりである t = { $from } s 以降のものである。
walkthrough-compare-predictor = 予測器
walkthrough-compare-tracking = 追従誤差のRMS (rad/s)
walkthrough-compare-speed = 速度推定誤差のRMS (rad/s)
walkthrough-compare-flux = 磁束推定誤差のRMS (Wb)
walkthrough-compare-nis = 平均NIS
walkthrough-compare-saturated = 電圧制限に達したサンプル
