# 核心关于运行的文字：各设置的含义、各预设展示的内容、运行的指标及其覆盖的运行区段、解读指标时
# 必须同时看到的警告、启动暂态结束于何处，以及运行停止的原因。命令行界面按此文件的英文版输出
# （`imlab describe`、`imlab presets`、`imlab metrics`）；页面则使用读者的语言。键和字段名
# （k1、law.v1、ekf.q）、字段的取值（euler、rk4、box）、符号（ω_d、φa²、Rs、|i_s|）、单位、
# 公式以及论文的公式编号和图号（(38)、Fig 2）是链接和论文自身的写法：保持原样。

## 时间

# 以毫秒或秒表示的时间，至多 4 位有效数字。
time-ms = { $ms } ms
time-s = { $s } s

## 各设置的含义（其键、单位和范围由编码器给出）

# (0/1) 表示开关：0 关，1 开。

field-design = 设计：paper（论文，沿用所设的值）或 derived（由电机数据推导）
field-ref = 转速参考值类型
field-ref-value = 恒定转速
field-sine-amp = 正弦幅值
field-sine-freq = 正弦频率
field-sine-offset = 叠加在正弦上的常数
field-step-size = 阶跃幅度
field-step-time = 阶跃时刻
field-step-wn = 阶跃滤波器自然频率 ωn
field-ramp-start = 斜坡起始时刻
field-ramp-level = 斜坡平台值
field-ramp-slope = 斜坡斜率大小
field-ramp-hold = 斜坡平台持续时间
field-rev-start = 反转前升速的起始时刻
field-rev-level = 反转转速，从 +level 到 −level
field-rev-slope = 反转斜率大小
field-rev-hold = 反转前在 +level 的保持时间
field-ref-table = 以点 t:ω_d 的表给出的参考值，点与点之间按直线连接
field-psi_d = φa² + φb² 的磁链目标值
field-fw = 基速以上弱磁（0/1）
field-fw-base = 弱磁基速
field-k1 = 转速误差衰减速率 k1
field-k2 = 转矩误差衰减速率 k2 = a7 + a8 + k2s1
field-k3 = 磁链误差衰减速率 k3
field-k4 = 磁链导数误差衰减速率 k4
field-robust = 施加鲁棒项 (38) 和 (53)（0/1）
field-eps2 = (38) 中的 ε2：z2·(v2s2 + d̃2) 的界
field-h2 = (38) 中的 h2：|d̃2| 的界
field-eps4 = (53) 中的 ε4：z4·(v4s2 + d̃4) 的界
field-h4 = (53) 中的 h4：|d̃4| 的界
field-law-v1 = 你的第 1 步：虚拟控制 v1（为空：论文的 (26)）
field-law-v2 = 你的第 2 步：v2（为空：论文的 (34)）
field-law-v3 = 你的第 3 步：虚拟控制 v3（为空：论文的 (45)）
field-law-v4 = 你的第 4 步：v4（为空：论文的 (49)）
# backstepping 和 ifoc 是字段的取值：保持原样。
field-controller = backstepping（反步控制，论文）或 ifoc（经典无速度传感器 FOC 基线）
field-ifoc-bw_i = IFOC 电流环带宽
field-ifoc-bw_w = IFOC 转速环带宽
field-ifoc-bw_mras = IFOC MRAS 转速估计器带宽
field-ifoc-i_max = IFOC q 轴电流限幅
field-ifoc-ff = IFOC 转矩前馈 J·ω̇_d + T0 + Cf·ω_d（0/1）
# euler 和 rk4 是字段的取值：保持原样。
field-ekf = EKF 预测器：euler（欧拉，论文）或 rk4
field-ekf-q = 过程噪声 Q = q·Ts·I，所有状态共用一个数：电流为 A²/s，ω 为 (rad/s)²/s，磁链为 Wb²/s
field-ekf-q_speed = 仅加在转速状态上的过程噪声，Q_ωω = (q + q_speed)·Ts
field-ekf-r_std = 假设的电流噪声，R = r_std²·I
field-ekf-load = 将负载 a2 = T_L0/J 作为 EKF 状态估计（0/1）
field-ekf-q_load = 负载转矩的随机游走强度
field-ekf-load_std = 负载估计的初始标准差
field-ekf-rr = 将转子电阻 R_r 作为 EKF 状态估计（0/1）
field-ekf-q_rr = 转子电阻的随机游走强度
field-ekf-rr_std = R_r 估计的初始标准差
field-init_err = 初始相对估计误差
field-start = 初始状态：paper（2 A、2 A、0.5 Wb、0.5 Wb）或 magnetized（已励磁至磁链目标值）
field-perfect = 理想观测器：控制器获得真实状态（0/1）
field-noise = 电流测量噪声标准差
field-seed = 噪声种子
# 仿真电机（被控对象）的参数；模型参数（控制器和观测器所假设的）与之同名。
field-motor = 同时设定被控对象和模型的电机及其额定电流
field-plant-rs = 定子电阻 Rs
field-plant-rr = 转子电阻 Rr
field-plant-m = 互感 M
field-plant-ls = 定子电感 Ls
field-plant-lr = 转子电感 Lr
field-plant-j = 转子转动惯量 J
field-plant-np = 极对数 np
field-plant-t0 = 恒定负载转矩 T0
field-plant-cf = 黏性摩擦系数 Cf
field-model-rs = { field-plant-rs }
field-model-rr = { field-plant-rr }
field-model-m = { field-plant-m }
field-model-ls = { field-plant-ls }
field-model-lr = { field-plant-lr }
field-model-j = { field-plant-j }
field-model-np = { field-plant-np }
field-model-t0 = { field-plant-t0 }
field-model-cf = { field-plant-cf }
field-load-time = 未知负载阶跃的时刻
field-load-torque = 未知负载阶跃的大小
field-load-table = 以点 t:torque 的表给出的未知负载转矩，点与点之间按直线连接（代替阶跃）
field-vmax = 每个分量的电压限幅
field-duration = 仿真时长
field-ts = 采样周期 Ts
field-substeps = 每个采样周期内被控对象的 RK4 子步数
field-i_rated = 额定电流：额定相电流的幅值 |i_s|
field-rated-v = 额定电压，线电压有效值
field-rated-f = 额定频率
field-delay = 计算延时：u_k 延后一个采样周期施加（0/1）
field-delay-comp = 延时补偿：按一步预测 x̂(k+1|k) 计算控制量（0/1）
# box、circle 和 hex 是字段的取值：保持原样。
field-vlimit = 电压限幅：box（每个分量 ±vmax，论文）、circle（|u| ≤ vdc/√3）或 hex（两电平逆变器）
field-vdc = circle 和 hex 限幅及 PWM 所用的直流母线电压
field-pwm = 两电平逆变器，采样频率下的对称 PWM（0/1；vlimit 为 circle 或 hex）

## 各预设展示的内容（preset-NAME：预设 NAME）

# 描述中出现的预设名（sine200、load-step、rr-mismatch）是链接的写法：保持原样。

preset-sine200 = 论文 Fig 2：用 EKF 跟踪 0.5 sin(2π·200 t) rad/s；电流峰值超过电机的额定电流
preset-step = 论文 Fig 3：经 200 Hz 临界阻尼滤波器、在 50 ms 时从 0 到 0.5 rad/s 的阶跃
preset-ramp = 论文 Fig 4：梯形，以 ±400 rad/s² 升至 100 rad/s，保持，再返回
preset-sine200-1rad = 200 Hz 下幅值 1 rad/s：触及 400 V 电压限幅而饱和，跟踪误差超过 sine200 的三倍
preset-sine200-rk4 = Fig 2，但 EKF 预测器用 RK4 代替论文的欧拉法
preset-rr-mismatch = 保持 50 rad/s，电机的转子电阻比模型值高 10%：真实转速在数秒内从启动中恢复，并稳定在参考值之上（运行 6 s 可看到其结束）
preset-load-step = 保持 50 rad/s；在 0.15 s 时施加 5 状态 EKF 看不到的 2 N m 未知负载阶跃
preset-decay = 理想观测器，无噪声，ω_d ≡ 0：误差按设计的 1200/s 衰减，然后停在一个随采样周期减小而降低的底值
preset-ifoc-step = 经典基线：带 MRAS 的无速度传感器 IFOC，阶跃到 40 rad/s（MRAS 在零速附近失效）
preset-load-step-est = load-step，负载 a2 作为 EKF 状态（RK4 预测器）：在精确模型下转速能顶住未知阶跃，而电机的 R_r 比模型值低 3% 时则不能
preset-rr-mismatch-est = rr-mismatch，R_r 作为 EKF 状态（RK4 预测器）：没有缓慢的暂态，R̂_r 保持在电机的值附近
preset-sine200-drive = 200 Hz 能否经受真实驱动的考验？sine200 加上一个采样周期的计算延时、540 V 逆变器六边形限幅和 PWM
preset-high-gain = 增益 3000/s（论文的 2.5 倍）：欧拉 EKF 的预测误差经增益放大，使电压触及 400 V 限幅而饱和

## 运行的指标（`imlab metrics` 以 figure- 之后的部分称呼它们）

figure-transient_end = 启动暂态结束
figure-tracking_rms = ω − ω_d 的 RMS
figure-tracking_peak = |ω − ω_d| 峰值
figure-settling_time = 阶跃后 ω 的 2% 调节时间
figure-saturated_share = 处于电压限幅的采样点比例
figure-mean_nis = 平均 NIS
figure-mean_nis_low = 平均 NIS，一致滤波器 95% 区间的下端
figure-mean_nis_high = 平均 NIS，一致滤波器 95% 区间的上端
figure-current_peak = 定子电流峰值 |i_s|
figure-current_rms = 定子电流 RMS |i_s|
figure-current_rated = 额定电流 |i_s|（i_rated）
figure-ripple_peak = PWM 电流纹波峰值
figure-ripple_rms = PWM 电流纹波峰值在各周期上的 RMS
figure-flux_error_final = 最终磁链误差 |φ_r| − √ψ_d
figure-speed_error_final = 最终转速误差 ω − ω_d
figure-speed_estimate_error_final = 最终转速估计误差 ω − ω̂
figure-law_residual = 你的控制律相对其设计动态的最大残差（在整个运行及判定所抽取的状态上，相对于论文的控制律）
# 不属于运行的指标：挑战可以使用它。
figure-load_recovery_time = 负载阶跃后的负载恢复时间

## 指标所覆盖的运行区段

# $time 是时间（time-ms 或 time-s）：启动暂态结束的时刻。
window-after-transient = t ≥ { $time }
window-start-up = 启动阶段，t < { $time }
# $time 是参考值阶跃的时刻。
window-from-step = 从 { $time } 时刻的阶跃起
window-rating = 电机的额定值
# $time 是运行最后一个采样点的时刻。
window-last-sample = 最后一个采样点，t = { $time }
window-law-residual = 整个运行及判定所抽取的状态

## 运行结束时尚未达到的指标，在其数值处显示

# $time 是运行最后一个采样点的时刻。
unreached-not-settled = 运行结束时仍未稳定（t = { $time }）

## 解读运行指标时必须同时看到的警告

# $speed 是运行结束时的 ω − ω_d，$estimate 是 ω̂ − ω，$flux 是磁链幅值，$target 是其目标值 √ψ_d。
warning-runaway = 此次运行失控：结束时真实转速与参考值相差 { $speed } rad/s，转速估计与真实转速相差 { $estimate } rad/s，磁链为 { $flux } Wb，而目标值为 { $target } Wb。控制器调节的是 EKF 的估计值；定理 4.6 只在估计误差保持有界时才给闭环以界，而当估计误差无界时（启动误差仅靠电压限幅才被约束住，或低速下模型有误），电机就不受任何约束。
# $low 和 $high 是区间的两端。
warning-inconsistent-above = 此次运行中 EKF 不一致：其平均 NIS 为 { $nis }，远高于模型相符的滤波器的 95% 区间 { $low }–{ $high }。无论其区间带看起来多窄，其估计值以及控制器所依据的转速都可能远离真实值。
warning-inconsistent-below = 此次运行中 EKF 不一致：其平均 NIS 为 { $nis }，远低于模型相符的滤波器的 95% 区间 { $low }–{ $high }。它假设的噪声多于实际，因此跟随测量值的速度慢于其应有的速度。
# $figure 是指标的名称（law_residual）；$cause 说明它为何不是数值。
warning-not-following = 转速没有跟随其参考值：从 t = { $since } 到运行结束，ω − ω_d 始终超出 ±({ $share } % × |ω_d| + { $margin } rad/s)，结束时为 { $error } rad/s，此时 ω_d = { $reference } rad/s。
warning-not-following-window = 转速没有跟随其参考值：在指标的整个窗口内，即从 t = { $since } 到运行结束，ω − ω_d 始终超出 ±({ $share } % × |ω_d| + { $margin } rad/s)，结束时为 { $error } rad/s，此时 ω_d = { $reference } rad/s。
warning-not-finite = { $figure } 不是有限数：{ $cause }。

## 启动暂态结束于何处，以及为何在此

transient-nothing-recorded = 尚未记录任何数据
# 代替时间：在运行的前半段中从未满足该条件。
transient-never = 前半段中从未出现（不采用）
# $k 是增益 k1..k4 中最小者（1/s）；$time 是控制器的启动时间。
transient-backstepping = 最慢的设计误差衰减速率的 5 个时间常数（1/{ $k } s）= { $time }
# $bw 是 IFOC 电流环带宽 ifoc.bw_i（Hz）；$time 是控制器的启动时间。
transient-ifoc = IFOC 电流环的 5 个时间常数（1/(2π·{ $bw } Hz)）= { $time }
# $controller 是 transient-backstepping 或 transient-ifoc；$observer、$estimates、$flux 和 $speed
# 是时间或 transient-never；暂态在场景的第一个事件（阶跃或负载阶跃）处截断时 $end 为 event，
# 被限制为运行的一半时为 half，否则为 none；$at 是该事件的时刻或运行一半的时刻。
transient-reason = { $controller }，从观测器启动完成时起算；EKF 新息协方差稳定（2σ 区间带与其最终值相差在 10% 以内）：{ $observer }；EKF 估计值收敛（2 ms 窗口的平均 NIS 在其后半段水平的两倍以内，持续 5 ms）：{ $estimates }；磁链估计误差进入其后续 RMS 误差的 1.5 倍以内（持续 5 ms）：{ $flux }；转速估计误差进入其后续 RMS 误差的两倍以内（5 ms 窗口，持续 5 ms）：{ $speed }{ $end ->
        [event] ；在场景的第一个事件处截断，即 { $at }
        [half] ；限制为已记录运行的一半（{ $at }）
       *[none] {""}
    }

## 运行停止的原因

# $t 是该采样点的时刻（s）；$signal 是越界的状态（omega、i_sa、phi_a…）；
# $value 是其值，以科学计数法表示（1.2e5、NaN）。
sim-diverged = 在 t = { $t } s 发散：{ $signal } = { $value } 越出其界限
# $column 是运行 CSV 的一列；$value 是 inf、-inf 或 NaN。
sim-not-finite = 在 t = { $t } s 停止：列 '{ $column }' 将记录 { $value }，不是有限数
# $error 是 control-* 消息。
sim-control = 控制器在 t = { $t } s 失败：{ $error }
# $formula 是学生输入的控制律；$value 是 inf、-inf 或 NaN；$reading 是
# sim-law-reads-nothing 或 sim-law-reads。
sim-law = 你的 law.v{ $step } = { $formula } 在 t = { $t } s 给出 { $value }，{ $reading }
sim-law-reads-nothing = 且不读取任何信号
# $signals 列出控制律读取的名称及其在该处的值（x1h = 52.3, z1 = 0.01）。
sim-law-reads = 此时 { $signals }
# $flux 和 $min 以科学计数法表示（Wb²）。
control-singular = 解耦矩阵 (55) 奇异：估计磁链 x̂4² + x̂5² = { $flux } Wb² 低于 { $min } Wb²
control-law = 第 { $step } 步的控制律给出 { $value }，不是有限数
pin-room-full = 最多只能固定 { $max } 个运行；请先取消固定一个
pin-legend-same = 相同场景
overlay-ts-differs = 固定的运行 { $scenario } 的采样周期为 Ts = { $pinned } s，当前运行为 { $current } s：叠加需要相同的 Ts
