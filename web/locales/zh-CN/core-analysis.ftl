sweep-not-settled = 未稳定：在最后 { $periods } 个周期中，从前一半到后一半，ω 的增益变化了 { $gain } dB，相位变化了 { $phase }°（稳定的标准：在 ±{ $gain-bound } dB 和 ±{ $phase-bound }° 以内）

## 模型误差图的轴和种子：被拒绝的原因，以及轴的名称。
map-axis-form = 轴 '{ $axis }'：应为 KEY=LO..HI:N，例如 plant.rr=-10%..+10%:11 或 k1=-20%..+20%:5
map-axis-unknown = 轴 '{ $axis }'：{ $key } 不是场景字段
map-axis-not-numeric = 轴 '{ $axis }'：{ $key } 不是数值；误差图只能改变数值字段
map-axis-whole = 轴 '{ $axis }'：{ $key } 只取整数；请用取值连续的字段作误差图
map-axis-inactive = 轴 '{ $axis }'：{ $key } 在此场景中不起作用，因此每个格子的运行结果都会相同
map-axis-end = 轴 { $key }：{ $end } '{ $text }'：应为数值或百分数，如 -10%
map-axis-mixed = 轴 '{ $axis }'：LO 和 HI 必须同为数值或同为百分数
map-axis-count = 轴 { $key }：N '{ $text }'：应为 1 至 { $max } 的整数
map-axis-zero = 轴 '{ $axis }'：{ $other } 为 0，因此相对于它的相对误差也为 0；请用数值给出 { $key }
map-axis-order = 轴 { $key }：LO（{ $lo }）大于 HI（{ $hi }）
map-axis-against-model = { $key } 相对于模型（%）
map-axis-against-motor = { $key } 相对于电机（%）
map-axis-against-base = { $key } 相对于基准值（%）
map-axis-unit = { $key }（{ $unit }）
map-seeds-form = 种子 '{ $seeds }'：应为 A..B，取 0 至 { $max } 的整数
map-seeds-order = 种子 '{ $seeds }'：第一个种子大于最后一个种子
map-seeds-many = 种子 '{ $seeds }'：共 { $count } 个种子，超过误差图可运行的 { $max } 个
map-seeds-twice = 种子给出了两次：请只给出一次
map-axes-count = { $count } 个轴：误差图只能有一个或两个轴
map-axes-repeated = 两个轴都改变 { $key }：请改变两个不同的字段
map-axes-sides = 两个轴分别改变 { $first } 和 { $second }，即同一参数的两侧：请只改变其中一侧，用数值或相对于另一侧的相对误差给出
map-no-seeds = 没有种子：误差图至少要运行一个种子
map-runs-many = 误差图需要 { $runs } 次运行（{ $cells } 个格子 × { $seeds } 个种子），超过允许的 { $max } 次；请减少取值点或种子
map-cell-refused = { $key }={ $value }：{ $reason }
map-work = 误差图需要 { $work } 个被控对象步（{ $cells } 个格子 × { $seeds } 个种子 × 每次运行的步数），超过允许的 { $max } 步；请减少取值点或种子，或缩短 'duration'
map-law-work = 误差图的自定义控制律需要 { $work } 次运算（{ $cells } 个格子 × { $seeds } 个种子 × 每次运行至多 { $per-run } 次），超过允许的 { $max } 次；请最多使用 { $runs } 次运行（格子 × 种子）、缩短 'duration'，或改用运算量更小的控制律

## 推导设计（design=derived）：每个值背后的规则及其理由。
# $voltage：额定线电压（V，有效值）；$frequency：额定频率（Hz）。
design-rule-vdc = √2 × { $voltage } V，即整流后的线电压；vlimit=circle，因此电压限幅为额定相电压的幅值 vdc/√3
design-rule-flux = { $voltage } V、{ $frequency } Hz 空载时的转子磁链 M·V/|Rs + jωLs|：电机自身的励磁
design-rule-flux-capped = 限制在 M·i_rated/√2（{ $voltage } V、{ $frequency } Hz 下的空载磁链要求更高）：励磁电流为转矩留出 i_rated² 的一半
design-rule-psi = 磁链的平方，即 φa² + φb² 的目标值
design-rule-id = 励磁电流，即磁链除以 M：flux/M
# $i_rated：额定电流幅值（A）。
design-rule-iq = 转矩电流 √({ $i_rated }² − i_d²)：额定电流的其余部分
design-rule-torque = 额定电流和额定磁链下的转矩 (3/2)·np·(M/Lr)·flux·i_q
design-rule-accel = 额定加速度 torque/J（转矩除以 J）：电机在额定电流下所能实现的反转斜率
# $share：占电压限幅的百分比。
design-rule-base = 基速：在此转速下，额定磁链和额定转矩电流在稳态时需要电压限幅的 { $share }%；高于基速时 fw=1 按 base/ω 降低磁链，使反电动势保持不变，其余电压作为电流环的裕量
# $kts：k·Ts；$share：占电压限幅的百分比；$sigma：漏感 σ（H）。
design-rule-gain-ts = k2 = k3 = k4 = { $kts }/Ts：每个误差每个采样周期可减少自身的 { $kts }，与论文在 20 kHz 下的 1200/s 相同；电压约束（限幅的 { $share }% 除以 σ·i_rated，σ = { $sigma } H）更高
design-rule-gain-voltage = k2 = k3 = k4 = 电压限幅的 { $share }% 除以 σ·i_rated（σ = { $sigma } H）：以该速率消除额定电流大小的误差需要四分之一的电压；采样约束 { $kts }/Ts 更高
# $ratio：k1 与 k2 之比。
design-rule-k1 = k1 = { $ratio } × k2：转速环比它所指令的电流更慢
design-rule-q = 过程噪声：模型就是电机本身，并与被控对象一样积分，因此 Q 只是维持滤波器增益不消失的下限；论文的 1e-3 会使这些电机的 NIS 低于其区间
design-rule-r = 电流传感器的噪声：R 与之相符
design-rule-r-none = 无传感器噪声：r_std = i_rated/1000，使滤波器增益保持有限
# $time：秒。
design-rule-q-load = torque²/{ $time } s：负载可在 { $time } s 内变化一个额定转矩
design-rule-load-std = torque/4：负载的初始不确定度为额定转矩的四分之一
# 场景含 design=derived 时，显示在预设说明的下方。
design-derived-heading = 由电机推导出的设计，以及每个值背后的规则
# $reason：核心无法推导该设计的原因。
design-failed = 无法显示推导出的设计：{ $reason }

## 由铭牌和试验数据得到的电机（`imlab motor`，“分析”选项卡）

# $key 为字段（rs、no-load、locked、nema、rated、j、np），$value 为输入的内容。
identify-bad-field = '{ $key }' = '{ $value }'：应为{ $expected }
identify-expect-positive = 正数
identify-expect-whole = 不小于 1 的整数
identify-expect-nema = A、B、C 或 D
identify-expect-rated = V,F,I：额定线电压（V，有效值）、额定频率（Hz）和额定电流（A，有效值），均为正数，以逗号分隔
identify-expect-reading = V,I,P,F：线电压（V，有效值）、线电流（A，有效值）、输入功率（W）和频率（Hz），以逗号分隔；功率可以为 0，其余均为正数
# $what 为代码中测量量的名称（voltage、current、frequency、power、rs）。
identify-not-positive = { $what } 必须为正数
# $test 为试验的字段：no-load 或 locked。
identify-power-too-high = '{ $test }'：试验功率超过了 √3·V·I 所能提供的值，因此其电阻会大于其阻抗
identify-no-rotor-resistance = 'locked'：堵转时的每相电阻 { $locked } Ω 不大于定子的 { $rs } Ω，因此没有剩余的转子电阻
identify-no-magnetising = 'no-load'：空载电抗不大于定子漏抗，因此没有剩余的励磁电抗
# $stator 和 $rotor 为漏抗的分配比例（0.5 和 0.5），$letter 为 NEMA 设计字母。
identify-heading = 由空载试验和堵转试验（IEEE Std 112）得到的等效电路，堵转漏抗按 { $stator }/{ $rotor } 分配给定子和转子（NEMA 设计 { $letter }）
identify-how-rs = 直流试验
identify-how-rr = 估计值：堵转电阻减去 rs，再经励磁支路折算为转子电阻
identify-how-m = 估计值：空载电抗减去定子漏抗
identify-how-ls = 估计值：m 加上堵转漏感中定子所占的部分
identify-how-lr = 估计值：m 加上堵转漏感中转子所占的部分
identify-how-given = 给定值
identify-link-heading = 预设 step 中的电机，同时作为被控对象和模型，带有其额定值和推导出的设计：
