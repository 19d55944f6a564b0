# 核心关于某一步自定义控制律的消息：公式被拒绝的原因，以及按该步设计的误差动态对控制律所作的
# 判定。命令行界面按此文件的英文版输出；页面则使用读者的语言。名称（x1h、k1s1、v1、z2）、函数
# （sqrt）、公式（ż1 = −k1·z1 + z2、a3·ω_d）、设置（law.v1）、论文的公式编号（(28)）和引用的
# 输入是公式语言和论文自身的写法：保持原样。引用的输入保留其引号。

## 公式被拒绝


## 某一步的自定义控制律被拒绝或缺失


## 对某一步自定义控制律的判定

# $designed 是该步设计的误差动态（ż1 = −k1·z1 + z2）；$output 是控制律给出的虚拟控制（v1）；
# 当该步依据学生自己写的上一步控制律 $before（v1 或 v3）判定时，$own 为 yes；$worst 是与其
# 相对自身大小的偏差（2e-16）；$draws 是抽取的状态数；$caveats 是 law-caveat-* 消息之一。
law-designed = 你的第 { $step } 步{ $own ->
        [yes] 在你自己的 { $before } 下给出了设计的动态 { $designed }：你的 { $output } 与给出该动态的值一致
       *[no] 给出了设计的动态 { $designed }：你的 { $output } 与论文的一致
    }，在 { $draws } 个随机抽取的状态和参数值上，相对偏差不超过 { $worst }。{ $caveats }
# 同 law-designed；$unit 是 $output 的单位；$difference 是 law-difference 或
# law-difference-unnamed。
law-not-designed = 你的第 { $step } 步{ $own ->
        [yes] 在你自己的 { $before } 下未给出设计的动态 { $designed }：你的 { $output }（{ $unit }）与给出该动态的值不同
       *[no] 未给出设计的动态 { $designed }：你的 { $output }（{ $unit }）与论文的不同
    }，在 { $draws } 个随机抽取的状态上，相对偏差最大达 { $worst }。{ $difference }{ $caveats }
# $cause 是 law-never-runs … law-not-finite 消息之一。
law-not-designed-because = 你的第 { $step } 步未给出设计的动态 { $designed }：{ $cause }。
law-cannot-judge = 无法判定你的第 { $step } 步：{ $cause }。
# $finding 是 law-term-*、law-mistake-*、law-scenario-values-only 和 law-rate-of-z 消息之一。
law-difference = 差异在于：{ $finding }。
law-difference-unnamed = 差异不是论文控制律中的某一项：请将你的控制律与这一步的推导逐项比较。

## 判定句之后附加的说明（每条说明以句后的空格开头）

law-caveat-none = {""}
# $names 列出学生上一步控制律所用到的、变化率未知的名称。
law-caveat-unchained = {" "}你的 { $before } 用到了 { $names }，而回路中没有其变化率（其中保存的是后续步骤选定的电压，或回路所缺的导数），因此这一步按论文的 { $before } 判定。
law-caveat-failed = {" "}你的 { $before } 在 { $draws } 个抽取的状态中有 { $failed } 个不给出有限值，这一步不在这些状态上判定。
# 两条说明都有：$unread 是 law-caveat-unchained，$failing 是 law-caveat-failed。
law-caveat-both = { $unread }{ $failing }

## 控制律与设计动态的偏差为何不是数值


## 错误的控制律错在何处

# $term 是论文控制律中带符号的一项（+a3·ω_d）。
law-term = 项 { $term }
# $part 是项 $term 展开后的一部分。
law-term-part = 项 { $term } 的部分 { $part }
# $label 是 law-term 或 law-term-part。
law-term-missing = 缺少论文控制律中的{ $label }
law-term-wrong-sign = { $label } 的符号错误
law-term-twice = { $label } 出现了两次
# $factor 是控制律中该项相对论文该项的倍数。
law-term-scaled = { $label } 是应有值的 { $factor } 倍
law-scenario-values-only = 它仅在本场景的参数值和增益下与论文的控制律相等：某个参数或增益被写成了数值，而控制律需要的是其名称
# 控制律等于论文的控制律减去（或加上）$gain 乘以该步的误差 $z（z1）：$now 是此时误差的衰减
# 速率，$meant 是设计的衰减速率。
law-rate-of-z = 它等于论文的控制律{ $sign ->
        [minus] 减去
       *[plus] 加上
    } { $gain }·{ $z }：在本场景的参数下，你的 { $z } 以 { $now } /s 而不是 { $meant } /s 的速率衰减；请检查增益以及你的 { $z } 各项的符号

## 学生常犯的错误，控制律与之相符时指出

law-mistake-k1 = 它用了 k1，而 (28) 中是 k1s1 = k1 − a3
law-mistake-a3-x1h = 它用了 a3·x̂1，而 (27) 中是 a3·ω_d
law-mistake-k2 = 它用了 k2，而 (36) 中是 k2s1 = k2 − a7 − a8：于是 ż2 中的 −(a7 + a8)·z2 被留了下来
law-mistake-printed-dv1 = 它照搬了 (31) 印出的 v̇1，连同其两处印刷错误：a3·ω_d 的导数应为 a3·ω̇_d，却写成 a3·ω_d；â2 的导数应为其变化率（已知负载时为 0），却写成 â2
law-mistake-printed-dv1-wd = 它照搬了 (31) 印出的 v̇1：a3·ω_d 的导数应为 a3·ω̇_d，却写成 a3·ω_d
law-mistake-printed-dv1-a2 = 它照搬了 (31) 印出的 v̇1：â2 的导数应为其变化率（已知负载时为 0），却写成 â2
law-mistake-robust-2 = 它写出了 (38) 的鲁棒项 −h2²/(4·ε2)·z2，却没有乘以开关 robust，因此鲁棒项关闭时它仍起作用
law-mistake-psi-modulus = 它把 ψ_d 当作磁链幅值（写成 ψ_d²），而论文的 z3 = x̂4² + x̂5² − ψ_d 把它当作幅值的平方
law-mistake-factor-2 = 它在整个 ψ3 中丢掉了因子 2：x̂4² + x̂5² 的变化率是 2·(x̂4·x̂̇4 + x̂5·x̂̇5)
law-mistake-residual-rates = 它漏掉了 ψ4 中残差的链式法则项 2·(l41·x̂4 + l51·x̂5)·ẋ̃2 和 2·(l42·x̂4 + l52·x̂5)·ẋ̃3
law-mistake-drifts = 它用了模型的漂移项 f̂4、f̂5，而 ψ4 中是观测器的变化率 x̂̇4 = f̂4 + si4 和 x̂̇5 = f̂5 + si5：漏掉了注入项
law-mistake-drift-4 = 它用了模型的漂移项 f̂4，而 ψ4 中是观测器的变化率 x̂̇4 = f̂4 + si4：漏掉了注入项 si4
law-mistake-drift-5 = 它用了模型的漂移项 f̂5，而 ψ4 中是观测器的变化率 x̂̇5 = f̂5 + si5：漏掉了注入项 si5
law-mistake-factor-si4 = x̂̇4 的因子中漏掉了 si4：ψ3 中 2·x̂4·si4 的变化率给出 2·si4·x̂̇4
law-mistake-factor-si5 = x̂̇5 的因子中漏掉了 si5：ψ3 中 2·x̂5·si5 的变化率给出 2·si5·x̂̇5
law-mistake-robust-4 = 它写出了 (53) 的鲁棒项 −h4²/(4·ε4)·z4，却没有乘以开关 robust，因此鲁棒项关闭时它仍起作用

## 控制律可用的名称及其含义（名称、符号和单位显示在旁边）

formula-name-x1h = 估计转子转速 ω̂（后验 x̂1）
formula-name-x2h = 估计定子电流 î_sa
formula-name-x3h = 估计定子电流 î_sb
formula-name-x4h = 估计转子磁链 φ̂_ra
formula-name-x5h = 估计转子磁链 φ̂_rb
formula-name-x2 = 测得的定子电流 i_sa
formula-name-x3 = 测得的定子电流 i_sb
formula-name-xt2 = 残差 x̃2 = x2 − x̂2
formula-name-xt3 = 残差 x̃3 = x3 − x̂3
formula-name-dxt2 = x̃2 的标称变化率：−(a7 + l21)·x̃2 − l22·x̃3
formula-name-dxt3 = x̃3 的标称变化率：−l31·x̃2 − (a7 + l32)·x̃3
formula-name-dx4h = x̂4 的观测器变化率：−a8·x̂4 − a9·x̂1·x̂5 + a10·x̂2 + si4
formula-name-dx5h = x̂5 的观测器变化率：−a8·x̂5 + a9·x̂1·x̂4 + a10·x̂3 + si5
formula-name-wd = 转速参考值 ω_d
formula-name-dwd = 其一阶导数
formula-name-ddwd = 其二阶导数
formula-name-psi-d = x̂4² + x̂5² 的磁链目标值
formula-name-si1 = 观测器对 x̂1 的注入：l11·x̃2 + l12·x̃3
formula-name-si2 = 观测器对 x̂2 的注入
formula-name-si3 = 观测器对 x̂3 的注入
formula-name-si4 = 观测器对 x̂4 的注入
formula-name-si5 = 观测器对 x̂5 的注入
formula-name-l11 = 观测器增益 L = K/Ts，第 1 行第 1 列
formula-name-l12 = 观测器增益，第 1 行第 2 列
formula-name-l21 = 观测器增益，第 2 行第 1 列
formula-name-l22 = 观测器增益，第 2 行第 2 列
formula-name-l31 = 观测器增益，第 3 行第 1 列
formula-name-l32 = 观测器增益，第 3 行第 2 列
formula-name-l41 = 观测器增益，第 4 行第 1 列
formula-name-l42 = 观测器增益，第 4 行第 2 列
formula-name-l51 = 观测器增益，第 5 行第 1 列
formula-name-l52 = 观测器增益，第 5 行第 2 列
formula-name-a1 = μ = 3·np·M/(2·J·Lr)：a1·(x3·x̂4 − x2·x̂5) 是转矩除以 J
formula-name-a2 = T0/J（EKF 估计负载时为估计值 â2）
formula-name-a3 = Cf/J
formula-name-a5 = α·β，其中 α = Rr/Lr，β = M/(σ·Lr)
formula-name-a6 = np·β
formula-name-a7 = γ = Rs/σ + α·β·M
formula-name-a8 = α = Rr/Lr
formula-name-a9 = np
formula-name-a10 = α·M
formula-name-b = 1/σ
formula-name-da2 = EKF 估计负载时为 â2 的变化率（其注入），否则为 0
formula-name-k1 = 转速误差衰减速率
formula-name-k2 = 转矩误差衰减速率（k2 = a7 + a8 + k2s1）
formula-name-k3 = 磁链误差衰减速率
formula-name-k4 = 磁链变化率误差衰减速率
formula-name-k1s1 = k1 − a3
formula-name-k2s1 = k2 − a7 − a8
formula-name-h2 = (38) 中 |d̃2| 的界
formula-name-eps2 = (38) 中的 ε2
formula-name-h4 = (53) 中 |d̃4| 的界
formula-name-eps4 = (53) 中的 ε4
formula-name-robust = 鲁棒项 (38) 和 (53) 开启时为 1，否则为 0
formula-name-z1 = 转速误差 x̂1 − ω_d
formula-name-z3 = 磁链误差 x̂4² + x̂5² − ψ_d
formula-name-v1 = 第 1 步的虚拟控制（若你写了，则为你的）
formula-name-z2 = 转矩误差 a1·(x3·x̂4 − x2·x̂5) − v1
formula-name-v3 = 第 3 步的虚拟控制（若你写了，则为你的）
formula-name-z4 = 磁链变化率误差 2·a10·(x2·x̂4 + x3·x̂5) − v3

## 控制律可调用的函数：每个函数连同其参数写出，并说明其结果（函数名及其参数是公式
## 语言的写法：保持原样）

formula-function-sqrt = sqrt(x)：平方根
formula-function-exp = exp(x)：指数
formula-function-ln = ln(x)：自然对数
formula-function-sin = sin(x)：正弦，x 的单位为 rad
formula-function-cos = cos(x)：余弦，x 的单位为 rad
formula-function-tanh = tanh(x)：双曲正切
formula-function-abs = abs(x)：绝对值
formula-function-sign = sign(x)：−1、0 或 1
formula-function-atan2 = atan2(y, x)：(x, y) 的角度（rad）
formula-function-min = min(a, b)：较小者
formula-function-max = max(a, b)：较大者
formula-function-sat = sat(x, m)：x 限制在 [−m, m] 内
