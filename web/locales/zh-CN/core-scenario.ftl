# 核心关于场景的消息：链接、设置或运行被拒绝的原因。命令行界面按此文件的英文版输出；页面则使用
# 读者的语言。字段名、键、值、预设和设置（v=1、preset=NAME、'duration'、'ts'、law.v2、pwm=1）
# 是链接自身的写法：保持原样。引用的输入保留其引号。

## 场景被拒绝

scenario-missing = 缺少字段 '{ $key }'（场景以 v={ $version }&preset=NAME 开头）
scenario-unsupported-version = 字段 'v' = '{ $value }'：不支持的编码版本，允许：{ $version }
# $presets 列出各预设的名称。
scenario-unknown-preset = 字段 'preset' = '{ $name }'：未知的预设，允许：{ $presets }
scenario-unknown-key = 字段 '{ $key }' 不是场景字段（设置表单和 `imlab describe` 列出了所有字段）
scenario-duplicate-key = 字段 '{ $key }' 出现了不止一次
scenario-malformed = '{ $piece }' 不是 key=value 形式
# $expected 是 scenario-expected-* 消息之一。
scenario-bad-value = 字段 '{ $key }' = '{ $value }'：无效，应为{ $expected }
# $allowed 是 scenario-allowed-* 消息之一。
scenario-out-of-range = 字段 '{ $key }' = { $value }：超出范围，允许：{ $allowed }
# $reference 是场景的参考值类型（step、sine、ramp…）。
scenario-not-applicable = 字段 '{ $key }' 不适用于参考值类型 '{ $reference }'（请先设置 ref=）
# $which 是 "plant" 或 "model"，即字段的前缀；$error 是 param-* 消息之一。
scenario-physics = { $which ->
        [plant] 被控对象（{ $which }）
       *[model] 模型（{ $which }）
    }参数：{ $error }
# $error 说明公式在何处、因何被拒绝。
scenario-bad-formula = 字段 '{ $key }'：{ $error }
scenario-refused = 字段 '{ $key }'：{ $why }
scenario-law-fw = 第 3 或第 4 步的自定义控制律是按恒定的磁链目标值写的，而 fw=1 会改变该目标值；请关闭 fw 或将该控制律留空
scenario-design = 字段 'design' = 'derived'：{ $why }
design-no-voltage = 额定电压只为稳态运行留出 { $available } V，而额定磁链加额定电流即使在静止时也需要 { $needed } V
scenario-too-long = 场景长 { $bytes } 字节，超过允许的 { $max } 字节（{ $kib } KiB）

## 字段接受的取值

scenario-expected-formula = 以 UTF-8 百分号编码的公式
scenario-expected-one-of = 以下之一：{ $options }
scenario-expected-number = 十进制数
# 点表：以 t:value 对给出的参考值或负载转矩。
scenario-expected-table = 以逗号分隔的点 t:value，例如 0:0,0.1:100，各数均为十进制数
scenario-expected-table-length = 至多 { $max } 个点；此表有 { $count } 个
scenario-expected-table-rising = 逐点递增的时间；{ $after } s 并不在 { $before } s 之后
scenario-expected-table-time = 0 到 { $max } s 之间的时间；{ $t } s 超出范围
# $unit 是取值的单位（rad/s）；$before 和 $after 是两个点的时间。
scenario-expected-table-slope = 点与点之间每秒至多 { $max } { $unit } 的变化；从 { $before } s 到 { $after } s 的变化更快
scenario-allowed-choice = { $options }
scenario-allowed-formula = 由第 { $step } 步可用的名称构成的公式（`imlab describe` 列出了这些名称），或为空
# $values 是取值的范围（scenario-allowed-unit）。
scenario-allowed-table = 至多 { $max } 个点 t:value，时间从 0 递增到 { $duration } s，取值 { $values }；点与点之间按直线连接，第一个点之前和最后一个点之后保持不变
# 字段的范围："0 < k1 ≤ 1000000"；$below 是 < 或 ≤。
scenario-allowed-range = { $min } { $below } { $key } ≤ { $max }
# $range 是上面的范围，其后附单位："0 < k1 ≤ 1000000 (1/s)"。
scenario-allowed-unit = { $range } ({ $unit })
scenario-allowed-whole = { $range }，整数
scenario-allowed-pwm = pwm=1 须配合 vlimit=circle 或 hex：两电平逆变器无法输出矩形限幅的顶点

## 运行规模过大

scenario-too-many-samples = 'duration'/'ts' = { $duration } s / { $ts } s = { $samples } 个采样点，超过允许的 { $max } 个；请缩短 'duration' 或增大 'ts'
scenario-shorter-than-sample = 'duration' = { $duration } s 短于一个采样周期 'ts' = { $ts } s
# $how 是 scenario-work-* 消息之一；运行含 PWM 时 $pwm 为 yes。
scenario-too-much-work = 运行的计算量为 { $samples } 个采样点（'duration'/'ts' = { $duration } s / { $ts } s）× 每个采样点 { $per_sample } 个被控对象 RK4 步（{ $how }）= { $work } 步，超过允许的 { $max } 步；请减小 'substeps' 或 'duration'，或增大 'ts'{ $pwm ->
        [yes] ，或关闭 'pwm'
       *[no] {""}
    }
scenario-work-substeps = 'substeps' = { $substeps }
scenario-work-substeps-pwm = 'substeps' = { $substeps }，作用于 7 个 PWM 区间中的每一个
scenario-work-prediction = { $plant }，另加理想观测器预测所用的 { $substeps } 步（'delay.comp'）
# $parts 列出 scenario-law-work-step 和 scenario-law-work-rates 消息。
scenario-law-work = 控制律的计算量为 { $samples } 个采样点（'duration'/'ts' = { $duration } s / { $ts } s）× 每个采样点 { $per_sample } 次运算（{ $parts }）= { $work }，超过允许的 { $max }（一次正弦或余弦计 64 次运算，一次乘方计 32 次，exp、ln、tanh 和 atan2 各计 12 次）；请把控制律写成每个采样点至多 { $fits } 次运算，或把 'duration' 缩短到 { $duration_fit } s，或把 'ts' 增大到 { $ts_fit } s
scenario-law-work-step = law.v{ $step } { $work }
scenario-law-work-rates = 自定义 v1 和 v3 的变化率 { $work }
# 调用方可以只保留每第 n 个采样点时，$fewer 为 yes。
scenario-trace-too-large = 记录 { $rows } 个采样点 × { $columns } 列需要 { $mib } MiB，超过允许的 { $max } MiB；请缩短 'duration' 或增大 'ts'{ $fewer ->
        [yes] ，或保留更少的采样点（增大 'every'）
       *[no] {""}
    }
sweep-run-too-large = 每次扫描运行都要保存其 { $samples } 个采样点，共 { $mib } MiB，超过允许的 { $max } MiB；请缩短扫描的运行时长或增大 'ts'

## 不符合物理的电机参数

param-not-positive = { $name } = { $value } 必须是 > 0 的有限数
param-negative = { $name } = { $value } 必须是 ≥ 0 的有限数
param-sigma = 漏感 σ = Ls − M²/Lr = { $sigma } H 必须 > 0（M = { $m }，Ls = { $ls }，Lr = { $lr }）：M² 必须小于 Ls·Lr
scenario-allowed-every = 1 ≤ every

## 扫描的运行被拒绝

sweep-allowed-amp = 扫描要求 0 < sine.amp
sweep-allowed-nyquist = 低于奈奎斯特频率 1/(2·Ts) = { $nyquist } Hz
sweep-allowed-period = 拟合窗口内至少有一个周期：对于 { $duration } s 的运行，freq ≥ { $least } Hz
# $reason 是 sweep-unresolved 或 sweep-too-small。
sweep-allowed-measurable = 扫描能够测量的幅值：{ $reason }；请增大幅值
sweep-unresolved = 在拟合窗口上对 ω_d 本身的拟合得到 { $found } rad/s，偏差超过 { $tolerance }%（幅值的平方下溢，或偏移加幅值舍入后等于偏移 { $offset } rad/s）
# $name 是指标的列名，$value 是其值（NaN 或 inf）。
sweep-too-small = 在 { $freq } Hz 处，响应读数为 { $name } = { $value }，太小，无法拟合

## 列表

# 核心给出的列表中各项之间的分隔符（“law.v1 12、law.v2 40”）。
core-list-separator = {"、"}
field-idle = 在 { $because } 时，{ $key } 不起作用
