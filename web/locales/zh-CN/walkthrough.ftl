# 设计详解（web/teaching/walkthrough*.js）：各部分的标题、正文、注释、框图、图的标题及其信号标签、
# 步骤的自定义控制律、稳定性报告以及 EKF 预测器的比较。公式不在此处：它们保持论文的写法。
# 关于一次运行的数值都是变量，以测量表（web/teaching/measurements/walkthrough.csv）中的行命名。
# 译文保留英文消息中的每个变量，且不写出英文未给出的任何数字。
# 正文中的花括号（如 u_{"{"}k−1{"}"}）写作 {"{"} 和 {"}"}。

## 第 1 部分（walkthrough-text.js）：电机模型 (2)

walkthrough-model-title = 1. 电机模型 (2)
walkthrough-model-prose-1 = 状态为转子转速 ω = x1、静止 a–b 坐标系中的定子电流 i_sa, i_sb = x2, x3 和转子磁链 φ_ra, φ_rb = x4, x5。只有电流是测量量；电压 u1, u2 是输入。
walkthrough-model-prose-2 = 转矩除以转动惯量为 a1(x3·x4 − x2·x5)，单位为 rad/s²：即电流与磁链的叉积（a1 = 3n_pM/(2JL_r) 已含 1/J，乘以 J 即得以 N m 计的转矩）。负载项 a2 + a3·x1 是常数 T0 与摩擦 Cf·ω 之和除以 J。下面的集总参数由核心根据当前所用的电机参数算出；被控对象（仿真的电机）与模型（EKF 和控制器所假设的）可以不同。
walkthrough-model-note = 此处 σ 的单位为亨利：论文中的 σ = L_s − M²/L_r 是从定子侧看的总漏感（暂态电感），而不是定子自身的漏感 L_s − M；许多教材改用无量纲的 σ = 1 − M²/(L_sL_r)。
walkthrough-model-plot-title = 转速与磁链

## 第 2 部分（walkthrough-text.js）：扩展卡尔曼滤波器 (10)–(20)

walkthrough-ekf-title = 2. 扩展卡尔曼滤波器 (10)–(20)
walkthrough-ekf-prose-1 = EKF 根据测量电流和施加的电压估计全部五个状态。它用经前向欧拉法离散化的模型 (10) 进行预测，用雅可比矩阵 (11) 线性化，并用新息进行校正：新息即测量电流减去预测电流。
walkthrough-ekf-prose-2 = Q（过程噪声：每个状态上为 q·Ts，另在转速上单独加 q_speed·Ts）表示对模型的信任程度；R（测量噪声，r_std²·I）表示对传感器的信任程度。对单位各不相同的状态只用一个 q，这是论文的选择；q_speed 使转速估计值能够变化，而不必放松其余状态。增益 K_k 以一般形式 (4) 中观测器增益 L = K_k/Ts 的身份进入控制器：估计误差 x̃ 正是控制器必须容忍的。
walkthrough-ekf-prose-3 = 一致的滤波器，其新息约有 95% 的时间落在 ±2σ 区间内，归一化新息平方（NIS）的平均值为 2。本设计详解中的范围和界均取自 { $wt-ekf-euler-nis--draws } 次噪声抽样（种子 1 至 { $wt-ekf-euler-nis--draws }）。欧拉预测器跟不上 200 Hz 的电流：在 sine200 上，它的 NIS 平均值在每次抽样中都至少为 { $wt-ekf-euler-nis }，而 RK4 预测器的至多为 { $wt-ekf-rk4-nis }；请在下方比较两者。
walkthrough-ekf-prose-4 = 论文第 3.1 节提出了一种补救办法，但没有实现：把缓慢变化的量作为附加状态。旋钮 ekf.load 把 a2 = T_L0/J 作为随机游走加入（控制器随之使用 â2 及其变化率，即注入项 l_a·(x̃2, x̃3)）；ekf.rr 加入转子电阻（控制器的 a5、a7、a8、a10 随 R̂_r 变化）。最后两幅图把这两个估计值及其由 P 得出的 ±2σ 区间与真实值对比。附加状态会吸收模型所缺的一切，不论对错：在未知负载下，转子电阻状态会把负载当作电阻（见各课）。
walkthrough-ekf-note = 印刷版的 (13) 用 u_{"{"}k|k−1{"}"} 进行预测；而在上一个采样周期内起作用的电压是 u_{"{"}k−1{"}"}，(10) 用的是它，这里的滤波器也是如此。Joseph 形式把协方差更新 (19) 写成两个对称项之和，对任意增益 K，每一项都是半正定的：与简式 (I − K_kC)P_{"{"}k|k−1{"}"} 相比，舍入误差远不容易使 P 失去这两种性质，尽管这并无保证。
walkthrough-ekf-plot-title = 新息 ỹ_a 及其由 S_k 得出的 ±2σ 区间
walkthrough-ekf-plot4-title = 归一化新息平方及其 95% 区间（χ²，自由度 2）
walkthrough-ekf-plot2-title = 转速估计值及其方差
walkthrough-ekf-plot3-title = 磁链幅值：真实值与估计值
walkthrough-ekf-plot5-title = 负载转矩：估计值 â2·J 及其 ±2σ 区间，以及真实值
walkthrough-ekf-plot6-title = 转子电阻：估计值及其 ±2σ 区间，以及电机的实际值

## 第 3 部分（walkthrough-text.js）：从观测器到控制器：(4) 与 (5)

walkthrough-bridge-title = 3. 从观测器到控制器：(4) 与 (5)
walkthrough-bridge-prose-1 = 控制器从不直接看到电机的状态，只看到观测器的估计值 x̂ 和测量电流 x2, x3。记估计误差为 x̃ = x − x̂。它有两个分量是测量得到的：电流残差 x̃2 = x2 − x̂2 和 x̃3 = x3 − x̂3。另外三个不是：转速误差 x̃1 和磁链误差 x̃4, x̃5。
walkthrough-bridge-prose-2 = 论文针对一般形式 (4) 的观测器设计控制器：用估计值复制模型 (2)，再加上注入项 si_i = l_i1·x̃2 + l_i2·x̃3 (5)，这一校正项按测量残差拉动各估计值。若看作一步前向欧拉，EKF 的更新在第 2 至 5 行具有这一形式，其中 L = K_k/Ts，残差为先验残差 y_k − Cx̂_{"{"}k|k−1{"}"} (15)。第 1 行只是近似如此：EKF 的转矩项用的是估计电流 x̂2, x̂3，而 (4) 用的是测量电流 x2, x3。这里的控制器使用后验残差 y_k − Cx̂_{"{"}k|k{"}"} = (I − CK_k)(y_k − Cx̂_{"{"}k|k−1{"}"})，它与控制器所用的后验估计 x̂_{"{"}k|k{"}"} 下的 x̃ = x − x̂ 相符；两种残差只有在 CK_k 很小时才一致。
walkthrough-bridge-prose-3 = 用 (2) 减去 (4) 即得下面的误差动态。控制器要对测量残差求导（它们出现在 v1 和 ψ3 中），而其导数包含未测量的 x̃1, x̃4, x̃5。每个这样的导数都被分成两部分：标称残差动态，即 x̃1 = x̃4 = x̃5 = 0 时 ẋ̃2 和 ẋ̃3 的值，由控制器计算；其余部分则无法计算。设计还把 L 视为常数：下文各处均忽略 L̇。
walkthrough-bridge-prose-4 = 这就是论文标题所说的一体化设计：观测器的误差动态包含在控制器的设计之中，未知项只出现在对测量电流或残差求导之处，即第 2 步（ż2 含 ẋ2、ẋ3 和 v̇1）和第 4 步（ż4 含注入项 si4、si5 的变化率）。第 1 步和第 3 步没有未知项。在这两步中，未知项被归并为 d̃2 和 d̃4，并作为有界扰动处理。采用精确模型时，未知项仅此而已；模型若与电机不同，还会在 ż2 和 ż4 中加入其自身的项，而论文的 d̃2 和 d̃4 并不包含这些项。
walkthrough-bridge-prose-5 = 这种一体化所取代的，是论文摘要中提到的时间尺度分离：使观测器比控制器快得多，以致控制器可以把其估计值当作状态。下面的控制律仍在状态反馈控制律使用 x 的地方使用 x̂，即确定性等价的形式；这一设计所增加的是，估计误差作为在假设 4.2 下有界的 d̃2 和 d̃4 进入其李雅普诺夫论证，而不是被假设为不存在。
walkthrough-bridge-figure = 控制器与观测器，同论文的图 1：控制器只能通过 EKF 的估计值、增益和残差以及测量电流来了解电机。
    .alt = 框图：参考值以及 EKF 的估计值、增益和残差输入反步控制器；控制器输出的电压经过电压限幅后驱动电机；测量电流和施加的电压反馈回 EKF。
walkthrough-bridge-note = 论文把注入项写作 si_i(x̃2, x̃3)；这里 si_i 表示其值 l_i1·x̃2 + l_i2·x̃3。字母 ψ 既表示磁链目标 ψ_d，也表示下面各步中的已知项 ψ2、ψ3、ψ4：两者互不相关。

## 第 4 部分（walkthrough-text.js、walkthrough-laws.js）：第 1 步：转速环

walkthrough-step1-title = 4. 第 1 步：转速环
walkthrough-step1-prose-1 = 第 1 步调节估计转速：z1 = x̂1 − ω_d。由 (4) 的第一行可得其导数，即开环 (23)。把摩擦项围绕参考值拆分，−a3·x̂1 = −a3·z1 − a3·ω_d：电机自身的阻尼 −a3·z1 保留，而 −a3·ω_d 是已知项。
walkthrough-step1-prose-2 = 虚拟控制是某一步当作输入来处理的信号，尽管电机并没有这样的输入。第 1 步的虚拟控制是转矩项 a1(x3·x̂4 − x2·x̂5)，它由测量电流和估计磁链构成：要求它等于 v1（转矩除以转动惯量，单位 rad/s²），并把差额记为 z2 (24)。于是 (25) 成立。
walkthrough-step1-prose-3 = 取 v1 = v1a + v1s (26)。前馈 v1a (27) 抵消所有已知项；si1 是已知的，因为它只用到测量残差。反馈 v1s = −k1s1·z1 (28) 留下 (29)，即 ż1 = −k1·z1 + z2，其中 k1 = a3 + k1s1：k1s1 是速率 k1 中由控制器在电机自身阻尼 a3 之上附加的部分，因此 v1a 中是 a3·ω_d 而不是 a3·x̂1。第 1、2 步保留电机自身的阻尼；第 3、4 步则抵消其已知的一切。
walkthrough-step1-prose-4 = 第 1 步的李雅普诺夫函数为 V1 = ½z1²。沿 (29) 有 V̇1 = z1ż1 = −k1z1² + z1z2：除交叉项 z1z2 外为负，该交叉项由第 2 步抵消。
walkthrough-step1-prose-5 = 第 2 步需要 v̇1。在 L 为常数（忽略 L̇）的条件下对 (30) 求导：注入项的变化率为 l11·ẋ̃2 + l12·ẋ̃3，而 ẋ̃2、ẋ̃3 包含未测量的 x̃1, x̃4, x̃5（第 3 部分）。v̇1 的已知部分用标称残差动态代替它们；其余部分，即下式中的“…”，归入 d̃2。
walkthrough-step1-note = 印刷版的 (31) 在应为 a3·ω̇_d 和 dâ2/dt 之处写成了 a3·ω_d 和 â2（上式已改正）。“…”即 x̃1, x̃4, x̃5 各项：−(l11·a5 − l12·a6·x̂1)·x̃4 − (l12·a5 + l11·a6·x̂1)·x̃5 − (l11·a6·x5 − l12·a6·x4)·x̃1。
walkthrough-step1-plot-title = 第 1 步：z1、v1 = v1a + v1s 与转矩项
walkthrough-step1-plot3-title = 第 1 步：运行得到的 ż1（每个采样周期内的变化量除以 Ts）与设计值 −k1·z1 + z2 对比
walkthrough-law-1-intro = 自己推导 v1，并在下方用本部分的名称把它写成公式（x1h 表示 x̂1，wd 和 dwd 表示 ω_d 和 ω̇_d，si1、a2、a3、k1s1、z1；完整列表见下方），可使用 + − * / ^、括号和函数。一旦你按 Enter 或停顿片刻，它就以 20 kHz 代替论文的 (26) 运行；输入框为空时恢复论文的控制律。运行结束后，判定会在随机抽取的状态和参数值上，按设计的动态 ż1 = −k1·z1 + z2 检查你的控制律，下方的图则显示整个运行中的残差：对于能给出该动态的控制律，残差为零。
walkthrough-law-1-plot-title = 第 1 步：你的控制律的残差，ż1 与设计的 ż1 = −k1·z1 + z2 对比（你的 v1 减去论文的相应控制律）

## 第 5 部分（walkthrough-text.js、walkthrough-laws.js）：第 2 步：转矩环

walkthrough-step2-title = 5. 第 2 步：转矩环
walkthrough-step2-prose-1 = 第 2 步通过把 z2 驱向零，使转矩项跟随 v1；电压在这里首次出现。对 (24) 求导：ẋ2 和 ẋ3 带来 bu1 和 bu2，因此 v2 = b·a1(x̂4·u2 − x̂5·u1) 就是输入；x̂̇4、x̂̇5 取自 (4)；−v̇1 即 (31)。把控制器已知的部分归入 ψ2，并把转矩项写成 z2 + v1，即得 (32)。
walkthrough-step2-prose-2 = ψ2 汇集了所有已知部分：磁链和电流的动态、注入项 si4、si5 以及 v̇1 的已知部分。未测量的误差 x̃1, x̃4, x̃5 只通过 d̃2 (33) 进入（采用精确模型时；模型若与电机不同，还会在 ż2 中加入其自身的项）：它对这些误差是线性的，系数由 x̂、x 和 L 构成，因此只要 x̂、x、L 和 x̃ 有界，它就有界。论文用投影 (7)–(9) 使 x̂ 保持有界；这界住的是 x̂ 而不是 x̃，而且在投影起作用期间，x̂̇ 不再是 (4)，ψ2–ψ4 也不再精确。这里的 EKF 没有投影：除运行本身外，没有任何东西约束 x̂。
walkthrough-step2-prose-3 = 取 v2 = v2a + v2s (34)：v2a = −ψ2 − z1 抵消已知项以及 V̇1 中的交叉项 z1z2；v2s = −k2s1·z2 + v2s2 (36) 加入反馈，其中 k2 = a7 + a8 + k2s1，因为电机本身提供阻尼 a7 + a8。对于论文的电机，a7 + a8 = 232.7 /s，因此当 k2 = 1200 /s 时 k2s1 = 967.3 /s。
walkthrough-step2-prose-4 = 若 h2 是 |d̃2| 的界，鲁棒项 v2s2 = −h2²z2/(4ε2) (38) 就能压制 d̃2。取 V_s2 = ½(z1² + z2²) (39)，则 V̇_s2 = −k1z1² − k2z2² + z2(v2s2 + d̃2) ≤ −k1z1² − k2z2² + ε2 (40)。对于无界增长的 d̃2，任何有限的 h2 都做不到这一点：一旦 |d̃2| 超过 h2，z2(v2s2 + d̃2) 就可能超过 ε2。
walkthrough-step2-prose-5 = 哪些项归入 d̃2 是一种选择：(33) 把真实转速写成 x1 = x̂1 + x̃1，并把 x̂1 部分留在 ψ2 中；换一种拆分会在 ψ2 与 d̃2 之间移动一些项，而 ż2 不变。论文在这里依靠的是假设 4.2 (22)：它假定 x̃ 位于一个已知的盒形区域 [x̃_min, x̃_max] 内，断言此时 d̃2 有界，并把 h2 取为该界 (38)，正如第 4 步取 h4 (53)。它没有给出该区域或这些界的数值。这里 h2 和 h4 是设置项；下方的 d̃2 图和第 4 步的 d̃4 图在所显示的运行上测量这些项，这是针对该运行确定其大小的一种方法。ε2 则在 (59) 的底值 ε/λ 与 v2s2 给 z2 的衰减速率附加的速率 h2²/(4ε2) 之间权衡，而每隔 Ts 采样一次的回路只能承受远低于约 2/Ts 的速率；“鲁棒项与界 (59)”一课演示了一种选择。
walkthrough-step2-prose-6 = 对 z2 求导还会得到 −(a7 + a8)·z2，即电机自身的阻尼；印刷版的 (32) 漏掉了它，而 (36) 中的 k2 = a7 + a8 + k2s1 计入了它。
walkthrough-step2-note = 印刷版的 (35) 为 v2a = −ψ2 − d̃2 − z1：d̃2 是未知的，任何控制器都无法减去它；这里的控制器采用 −ψ2 − z1，把 d̃2 留给鲁棒项处理。
walkthrough-step2-shows-1 = 下图根据仿真的真实值计算 d̃2：电机实际的 ż2 减去控制器已知的各项，并以真实电流代替测量电流。它针对不带延时补偿的五状态 EKF 计算；对于带附加状态（ekf.load、ekf.rr）或带 delay.comp 的观测器，该图保持空白。h2 至少要等于 |d̃2| 的峰值，(38) 才能压制它：先在精确模型下于 step 上读取，再在有模型误差时（plant.j、plant.rr）读取。电机的 R_r 比模型值高 10%（plant.rr = 5.445）时，{ $wt-rrhigh-runaway--draws } 次抽样中有 { $wt-rrhigh-runaway } 次回路失控或失效：其中 { $wt-rrhigh-off } 次磁链发散，{ $wt-rrhigh-fail } 次控制器在运行结束前失效。在预设的 0.1 s 结束时，磁链为 { $wt-rrhigh-flux-min } 至 { $wt-rrhigh-flux-max } Wb，1 s 后为 { $wt-rrhigh1s-flux-min } 至 { $wt-rrhigh1s-flux-max } Wb，而 (33) 中 d̃2 的系数随 x 增大。
walkthrough-step2-plot-title = 第 2 步：z2 与 v2 = v2a + v2s
walkthrough-step2-plot2-title = 第 2 步：根据仿真真实值计算的 d̃2，与 ±h2 对比
walkthrough-step2-plot3-title = 第 2 步：运行得到的 ż2（每个采样周期内的变化量除以 Ts）与设计值 −k2·z2 − z1 对比（robust=1 时含鲁棒项）
walkthrough-law-2-intro = 自己推导 v2，并在下方用本部分的名称把它写成公式（v1 和 z2（来自第 1 步）、x2 和 x3、x4h 和 x5h、si4 和 si5、dxt2 和 dxt3、l11 和 l12、ddwd、a1 至 a10、k1、k1s1、k2s1；完整列表见下方），可使用 + − * / ^、括号和函数。一旦你按 Enter 或停顿片刻，它就以 20 kHz 代替论文的 (34) 运行；输入框为空时恢复论文的控制律。若第 1 步下有你自己写的 v1，你的 v2 就依据它来判定：它必须对你的 v1 求导，并采用你的 v1 所给出的 ż1。运行结束后，判定会在随机抽取的状态和参数值上，按设计的动态 ż2 = −k2·z2 − z1 检查你的控制律，下方的图则显示整个运行中的残差：对于能给出该动态的控制律，残差为零。
walkthrough-law-2-plot-title = 第 2 步：你的控制律的残差，ż2 与设计的 ż2 = −k2·z2 − z1 对比（你的 v2 减去能给出该动态的 v2：即论文的控制律，或在你自己的 v1 之后，对它求导所得的控制律）

## 第 6 部分（walkthrough-text.js、walkthrough-laws.js）：第 3 步：磁链外环

walkthrough-step3-title = 6. 第 3 步：磁链外环
walkthrough-step3-prose-1 = 第 3 步调节估计磁链幅值的平方：z3 = x̂4² + x̂5² − ψ_d (42)。其导数只需用到 (4)：ż3 = 2x̂4·x̂̇4 + 2x̂5·x̂̇5 − ψ̇_d，其中 a9 项相互抵消，下面仅用估计值写出。令 x̂2 = x2 − x̃2、x̂3 = x3 − x̃3，即可把虚拟控制 2a10(x2·x̂4 + x3·x̂5)（ż3 中由定子电流驱动的部分）与 ψ3 (43) 分开。
walkthrough-step3-prose-2 = ψ3 只取决于估计值和测量残差，因此第 3 步完全没有未知项：取 v3 = −ψ3 − k3·z3 (45)，则对于观测器自身的磁链估计值，ż3 = −k3·z3 + z4 (46) 在连续时间下精确成立。其李雅普诺夫函数为 V3 = ½z3²，V̇3 = −k3z3² + z3z4；交叉项由第 4 步抵消。
walkthrough-step3-prose-3 = 由于 v3 = −ψ3 − k3·z3，下一个误差 z4 (44) 为 z4 = ż3 + k3·z3：即 z3 未能按速率 k3 衰减的那部分变化率。
walkthrough-step3-prose-4 = 论文把反馈写成 v3s = −k3s1·z3，并取 k3 = k3s1 (46)：v3a 抵消全部 ψ3，包括磁链自身的衰减 −2a8·(x̂4² + x̂5²)，因此整个速率 k3 都来自控制器；而在第 1 步中，电机的阻尼 a3 是 k1 的一部分。
walkthrough-step3-note = 问题描述要求 x4² + x5² 跟踪 ψ_d²，但 (42) 减去的是 ψ_d：这里的 ψ_d 是幅值平方的目标值，单位为 Wb²。场景中的 psi_d 就是这一目标值：psi_d = 0.5 Wb² 要求磁链幅值 |φ| = 0.707 Wb。论文的仿真把“ϕ_d = 0.5”作为期望的磁链幅值，按字面理解是 0.5 Wb（0.25 Wb²）；各预设则把它当作幅值的平方，正如 (42) 的用法，即论文初始磁链 [0.5, 0.5] 的平方。
walkthrough-step3-shows-1 = z3 图显示的是观测器自身的磁链估计值相对于目标值的误差，而不是电机磁链的误差。在 step 上采用精确模型时，从 15 ms 起，其 RMS 在采用 EKF 时为 { $wt-z3-min } 至 { $wt-z3-max } mWb²，无测量噪声（noise=0）时为 { $wt-z3-quiet } mWb²：噪声经由新息进入 z3。采用理想观测器（perfect=1）时，其估计值就是电机的磁链，该 RMS 保持在 { $wt-z3-perfect-max } mWb² 以下。
walkthrough-step3-plot-title = 第 3 步：z3 与 v3 = v3a + v3s
walkthrough-step3-plot3-title = 第 3 步：运行得到的 ż3（每个采样周期内的变化量除以 Ts）与设计值 −k3·z3 + z4 对比
walkthrough-law-3-intro = 自己推导 v3，并在下方用本部分的名称把它写成公式（x4h 和 x5h、xt2 和 xt3、si4 和 si5、a8、a10、k3、z3；完整列表见下方），可使用 + − * / ^、括号和函数。一旦你按 Enter 或停顿片刻，它就以 20 kHz 代替论文的 (45) 运行；输入框为空时恢复论文的控制律。运行结束后，判定会在随机抽取的状态和参数值上，按设计的动态 ż3 = −k3·z3 + z4 检查你的控制律，下方的图则显示整个运行中的残差：对于能给出该动态的控制律，残差为零。
walkthrough-law-3-plot-title = 第 3 步：你的控制律的残差，ż3 与设计的 ż3 = −k3·z3 + z4 对比（你的 v3 减去论文的相应控制律）

## 第 7 部分（walkthrough-text.js、walkthrough-laws.js）：第 4 步：磁链内环与电压

walkthrough-step4-title = 7. 第 4 步：磁链内环与电压
walkthrough-step4-prose-1 = 第 4 步把 z4 驱向零；其输入 v4 = 2a10·b(x̂4·u1 + x̂5·u2) 是电压的第二个组合。由于 z4 = ż3 + k3·z3，有 ż4 = z̈3 + k3·ż3 = z̈3 + k3(−k3z3 + z4)。对 ż3 仅用估计值写出的形式（第 3 步的第一行式子）再求一次导，而不是对形式 (43) 求导，因为后者中的测量电流会带来一些相互抵消的未知项：x̂̇4、x̂̇5 项如下归并，x̂̇2 和 x̂̇3 带来电压（v4）和电流动态，而注入项的变化率 l41·ẋ̃2 + l42·ẋ̃3 和 l51·ẋ̃2 + l52·ẋ̃3 带来残差的导数。
walkthrough-step4-prose-2 = 在 2a10·(x2·x̂4 + x3·x̂5) 的导数中，ẋ2 和 ẋ3 (2) 中 a6 项的已知部分相互抵消，a6·x̂1·(x̂4·x̂5 − x̂5·x̂4) = 0，这就是 ψ4 中没有 a6 的原因；其余含 x̃1, x̃4, x̃5 的部分归入 d̃4。取 V_s4 = ½z3² + ½z4² (56)，则 V̇_s4 = −k3z3² − k4z4² + z4(v4s2 + d̃4) ≤ −λ4·V_s4 + ε4，其中 λ4 = 2·min(k3, k4)，积分即得 (57)，正如第 8 部分对 V 所做的那样。
walkthrough-step4-prose-3 = ψ4 对 ẋ̃2 和 ẋ̃3 采用标称残差动态（第 3 部分），并忽略 L̇：印刷版的 (47) 在 L̇ = 0 时成立。标称动态所遗漏的部分，即 ẋ̃2 和 ẋ̃3 中分别以 2(l41·x̂4 + l51·x̂5) 和 2(l42·x̂4 + l52·x̂5) 加权的 x̃1, x̃4, x̃5 项，就是 d̃4。
walkthrough-step4-prose-4 = 取 v4 = −ψ4 − z3 − k4·z4 + v4s2 (49)–(51)：−z3 抵消 V̇3 中的交叉项 z3z4，于是得到 (52)。v2 和 v4 一起通过解耦矩阵 (54) 确定两个电压，只要估计磁链不为零，该矩阵就可逆 (55)。随后电压限幅起作用：论文只给出 400 V 的限幅；矩形限幅（vlimit=box）把每个分量截断到 ±400 V，而圆形限幅和逆变器的六边形限幅（vlimit）则把整个矢量按比例缩小，保持其方向。限幅起作用期间，设计的误差动态不再成立。
walkthrough-step4-note = 印刷版的 (48) 在应为 a41、a42 之处写成了 a21、a22（上式已改正）。上面的 ψ4 是印刷版 (47) 重新归并后的形式：论文把 2a10(x̂4·si2 + x̂5·si3) 写成 2a10(l21·x̃2·x̂4 + …)，并把每个含 x̂̇4、x̂̇5 的乘积拆成两项。其 d̃4 与印刷版逐项相同。
walkthrough-step4-shows-1 = 下图绘出与 d̃2 一样根据仿真真实值计算的 |d̃4|，并与 ±h4 对比；要使 (53) 能压制它，h4 至少要等于其峰值。
walkthrough-step4-shows-2 = 在最初 5 ms 内，启动暂态所指令的电压远超限幅：指令 u_sa 的峰值在 step 上为 { $wt-cmd-step-min } 至 { $wt-cmd-step-max } V，在 rr-mismatch 上为 { $wt-cmd-rr-min } 至 { $wt-cmd-rr-max } V，且在 rr-mismatch 上限幅一直截断指令，直到 { $wt-clip-rr-min } 至 { $wt-clip-rr-max } ms。各图按该暂态之后的运行数据调整 y 轴；取消勾选图上方的“按启动暂态之后的数据调整 y 轴”即可看到它。
walkthrough-step4-plot-title = 第 4 步：z4、v4 以及限幅前后的电压
walkthrough-step4-plot2-title = 第 4 步：根据仿真真实值计算的 d̃4，与 ±h4 对比
walkthrough-step4-plot3-title = 第 4 步：运行得到的 ż4（每个采样周期内的变化量除以 Ts）与设计值 −k4·z4 − z3 对比（robust=1 时含鲁棒项）
walkthrough-law-4-intro = 自己推导 v4，并在下方用本部分的名称把它写成公式（v3 和 z4（来自第 3 步）、dx4h 和 dx5h、dxt2 和 dxt3、si2 至 si5、l41 至 l52、a5、a7、a8、a10、k3、k4、z3；完整列表见下方），可使用 + − * / ^、括号和函数。一旦你按 Enter 或停顿片刻，它就以 20 kHz 代替论文的 (49) 运行；输入框为空时恢复论文的控制律。若第 3 步下有你自己写的 v3，你的 v4 就依据它来判定：它必须对你的 v3 求导，并采用你的 v3 所给出的 ż3。运行结束后，判定会在随机抽取的状态和参数值上，按设计的动态 ż4 = −k4·z4 − z3 检查你的控制律，下方的图则显示整个运行中的残差：对于能给出该动态的控制律，残差为零。
walkthrough-law-4-plot-title = 第 4 步：你的控制律的残差，ż4 与设计的 ż4 = −k4·z4 − z3 对比（你的 v4 减去能给出该动态的 v4：即论文的控制律，或在你自己的 v3 之后，对它求导所得的控制律）

## 第 8 部分（walkthrough-text.js）：稳定性：定理 4.6

walkthrough-stability-title = 8. 稳定性：定理 4.6
walkthrough-stability-prose-1 = 取 V = ½(z1² + z2² + z3² + z4²) (58)，四个设计的误差动态给出 V̇ = −k1z1² − k2z2² − k3z3² − k4z4² + z2(v2s2 + d̃2) + z4(v4s2 + d̃4) (60)。交叉项 ±z1z2 和 ±z3z4 相互抵消：这正是 v2a 中的 −z1 和 v4a 中的 −z3 的用途。
walkthrough-stability-prose-2 = 证明只需再写三行。第一，若 |d̃2| ≤ h2（h2 即 (38) 中的 δ_d2，论文断言在假设 4.2 对 x̃ 的界 (22) 之下存在这样一个 d̃2 的界，但没有推导：d̃2 关于 x̃1, x̃4, x̃5 是线性的，其系数含有真实的 x1, x4, x5、估计值以及增益 l11, l12，因此 x̃ 的界只有在这些量保持有界时才能界住它），则由杨氏不等式可界住鲁棒项这一对：z2(v2s2 + d̃2) ≤ h2|z2| − h2²z2²/(4ε2) ≤ ε2，因为两者之差是一个完全平方。对 z4，以 h4 和 ε4 同理可得。第二，Σk_i·z_i² ≥ min(k_i)·Σz_i² = 2·min(k_i)·V = λV。因此 V̇ ≤ −λV + ε，其中 ε = ε2 + ε4。第三，比较步骤：e^(λt)·V 的变化率为 e^(λt)·(V̇ + λV) ≤ ε·e^(λt)；从 0 到 t 积分即得 (59)。
walkthrough-stability-prose-3 = V 把不同单位的平方量相加（z1 的单位为 rad/s，z2 为 rad/s²，z3 为 Wb²，z4 为 Wb²/s），ε2（rad²/s⁵）和 ε4（Wb⁴/s³）的单位也不同：(59) 对 SI 数值成立。它并不能原样推广到任意加权：取 V = ½Σw_i·z_i² 时，V̇ 的交叉项变为 (w1 − w2)·z1z2 和 (w3 − w4)·z3z4，只有当 w1 = w2 且 w3 = w4 时才相互抵消（权重不等会留下交叉项，从而降低 λ），除非把 (35) 中的耦合项 −z1 和 (50) 中的 −z3 分别重新缩放为 −(w1/w2)·z1 和 −(w3/w4)·z3。这些耦合项带有单位（SI 中为 1/s²），而简单求和掩盖了这一点。该界约束的是总和，对每个 ½z_i² 只能通过总和加以约束。图中把本次运行记录的 V 与该界进行比较。
walkthrough-stability-prose-4 = 该定理界住的是估计值的误差 z_i，而不是电机本身：真实的转速误差为 |x1 − ω_d| ≤ |z1| + |x̃1|。它假设在整个运行中 |d̃2| ≤ h2 且 |d̃4| ≤ h4；而这些界本身又预设了 x、x̂ 和 L 有界，这恰恰是定理的结论，并且被忽略的 L̇ 项既不在 ψ 中也不在 d̃ 中。当假设不成立时，它对真实电机没有给出任何结论。
walkthrough-stability-shows-1 = 在 EKF 有 10% 初始误差、采用精确模型时，电压限幅能稳住启动过程：有限幅时，sine200 在 { $wt-limit-runaway--draws } 次抽样中有 { $wt-limit-runaway } 次失控（电机的 R_r 比模型值高 10% 时，即使有限幅也有 { $wt-limit-rrhigh-runaway } 次），而没有限幅时（vmax=100000）有 { $wt-nolimit-runaway } 次，最终转速偏离最多达 { $wt-nolimit-off-max } rad/s，磁链最高达 { $wt-nolimit-flux-max } Wb。从正确的初始估计值出发（init_err=0），同样的无限幅运行在精确模型下每次抽样的跟踪误差 RMS 为 { $wt-exact-rms-min } 至 { $wt-exact-rms-max } rad/s；电机的 R_r 比模型值高 10% 时，即便如此也会失效：其 RMS 误差至少为 { $wt-exact-rrhigh-rms } rad/s，并在 { $wt-exact-rrhigh-runaway--draws } 次抽样中有 { $wt-exact-rrhigh-runaway } 次失控。
walkthrough-stability-plot-title = 李雅普诺夫函数 V(t) = ½Σz_i² 与界 (59) 对比，对数刻度

## 图中信号的图例标签（walkthrough-text.js、walkthrough-laws.js）

walkthrough-series-estimated = { $signal } 估计值
walkthrough-series-true = { $signal } 真实值
walkthrough-series-right = { $signal }（右轴）
walkthrough-series-right-unit = { $signal }（{ $unit }，右轴）
walkthrough-series-feedforward = { $term } 前馈
walkthrough-series-feedback = { $term } 反馈
walkthrough-series-run = { $signal }（运行所得）
walkthrough-series-designed = { $expression }（设计值）
walkthrough-series-load-true = T_L 真实值（T0 + 阶跃）
walkthrough-series-rr-motor = 电机的 R_r
walkthrough-series-u-commanded = u_sa 指令值 (V)
walkthrough-series-u-applied = u_sa 施加值 (V)
walkthrough-series-lyapunov = V(t) 李雅普诺夫函数
walkthrough-series-bound = 界 (59)
walkthrough-series-law-paper = 你的 { $output } − 论文的 { $output }
walkthrough-series-law-gives = 你的 { $output } − 给出 { $rate } 的 { $output }
walkthrough-nis-low = 2.5% 分位数
walkthrough-nis-high = 97.5% 分位数
walkthrough-stability-plot-unit = V（混合单位：½Σz_i²）

## 各部分的框架（walkthrough-sections.js、walkthrough.js）

walkthrough-diagram-label = “{ $section }”部分的示意图
walkthrough-equation-label = “{ $section }”部分的第 { $number } 个公式
walkthrough-run-shows = 运行结果说明
walkthrough-lumped-label = 被控对象与模型的集总参数
walkthrough-lumped-plant = 被控对象
walkthrough-lumped-model = 模型
walkthrough-stability-waiting = 运行一个场景，即可比较 V 与界。
walkthrough-compare-button = 在此场景下比较欧拉与 RK4 预测器
walkthrough-compare-label = 欧拉与 RK4 预测器对比
walkthrough-knobs = 设计旋钮
walkthrough-ifoc-note = 此场景运行的是经典 IFOC 基准。下面的反步控制各项是根据 EKF 估计值算出的，仅供比较；驱动电机的并不是它们。
walkthrough-equations-failed = 无法载入公式：请检查网络连接，然后重新打开设计详解。

## 稳定性报告（walkthrough-reports.js）：界 (59) 与整个运行中的 V 对比，
## 以及 V 超出界时按可能原因给出的补充说明。

walkthrough-stability-nothing = 没有记录任何数据。
walkthrough-stability-bound-robust = λ = 2·min(k) = { $lambda } 1/s，ε = { $eps }（鲁棒项开启）。
walkthrough-stability-bound-off = λ = 2·min(k) = { $lambda } 1/s，ε = { $eps }（鲁棒项关闭，因此界为 V(0)·e^(−λt)）。
walkthrough-stability-under =
    V 在{ $samples ->
       *[other] 全部 { $samples } 个采样点
    }上都保持在界之下。
walkthrough-stability-above =
    在 { $samples ->
       *[other] { $samples } 个采样点
    }中，有 { $outside } 个采样点的 V 高于界，首次出现在 t = { $first } s；其中 { $outsideSaturated } 个电压处于饱和（{ $saturated ->
       *[other] 共有 { $saturated } 个采样点饱和
    }）。
walkthrough-stability-cause-saturation = 这些采样点中大多数的指令电压超出限幅：饱和破坏了界所依赖的设计误差动态。
walkthrough-stability-cause-sampling = 采用理想观测器和精确模型时 d̃2 = d̃4 = 0，在连续时间下 V 将保持在界之下（增益相等时恰在界上）。采样回路会留下其自身的误差，在 z_i 中约为 Ts 量级：在 decay 上，V 停在一个底值上，而界继续下降，因此 V 最终远高于界；将 Ts 减半，底值变为原来的 { $wt-decay-halfts } 倍。转子电阻误差会加入其自身的扰动，远高于该底值：电机的 R_r 比模型值偏高、偏低 10% 时，在 decay 上 V 最终分别为底值的 { $wt-decay-rrhigh } 倍和 { $wt-decay-rrlow } 倍。转动惯量误差在 decay 上则不会如此：模型的转动惯量比电机偏高、偏低 20%（model.j = 0.024 和 model.j = 0.016）时，V 最终分别为底值的 { $wt-decay-jhigh } 倍和 { $wt-decay-jlow } 倍。
walkthrough-stability-cause-estimation-errors = 估计误差以 d̃2 和 d̃4 的形式进入；鲁棒项关闭时，没有任何东西约束 z2·d̃2 + z4·d̃4，因此该界（此时假设 d̃ = 0）不一定成立。
walkthrough-stability-cause-eps-or-sampling = ε 相对于实际的 d̃2、d̃4 太小，或者 20 kHz 采样引入了连续时间证明中不存在的误差。

## EKF 预测器的比较（walkthrough-reports.js）

walkthrough-compare-note = 同一场景、同一种子，只有 EKF 预测器不同；指标从 t = { $from } s（启动暂态结束）起统计，与指标栏相同。
walkthrough-compare-predictor = 预测器
walkthrough-compare-tracking = 跟踪 RMS (rad/s)
walkthrough-compare-speed = 转速估计 RMS (rad/s)
walkthrough-compare-flux = 磁链估计 RMS (Wb)
walkthrough-compare-nis = 平均 NIS
walkthrough-compare-saturated = 处于电压限幅的采样点
