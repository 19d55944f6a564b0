# 页面本身的标签、按钮、说明和消息，按显示它们的页面区域分组。
# 数值以变量传入，已按本语言的方式书写。名为 $reason、$warning、$description 或 $label 的变量
# 是仿真核心自己的文字，暂为英文；场景（$scenario）、字段的键（$key）、预设名（$preset）和命令
# 按原样书写，从不翻译。

## 页头

# 浏览器标签页的标题。
page-title = IM Lab：无速度传感器感应电机控制
# 应用的名称，显示在页面标题中。
page-name = IM Lab
page-skip-link = 跳到图
page-intro = 无速度传感器感应电机控制：EKF 观测器与四步反步控制器（Zhang, Wang, Bortoff 等，2015），在你的浏览器中以 20 kHz 仿真。
help-links =
    .aria-label = 关于 / 帮助
# 位于各指南链接之前。
help-links-intro = 关于 / 帮助：
help-student-guide = 学生指南
help-lecturer-guide = 教师指南
help-all-guides = 全部指南
language-menu = 语言

## 载入各课

# $reason 是浏览器给出的原因，为浏览器自己的文字。
lessons-not-loaded = 无法载入各课的文字：{ $reason }。请重新打开“课程”选项卡以重试。

## 多处共用的按钮

shared-cancel = 取消
# 把表格下载为 CSV 文件。
shared-csv = CSV

## 运行栏：预设、运行、状态行和链接

run-preset = 预设
run-button = 运行
run-settings = 设置
run-unrun = 设置已更改，尚未运行：请按“运行”或 Enter。地址和“复制链接”对应的是屏幕上的运行。
share-copy-link = 复制链接
# 下载各图的图像。
export-png = PNG
share-copy-embed = 复制嵌入代码
    .title = 复制一段 iframe 代码，按此场景显示“轨迹”选项卡中当前可见的图

## 结果：选项卡、视图栏和指标

results =
    .aria-label = 结果
tabs =
    .aria-label = 视图
tab-plots = 轨迹
tab-walkthrough = 设计详解
tab-lessons = 课程
tab-analysis = 分析
tab-challenge = 挑战
present-button = 演示模式
    .title = 为投影仪放大文字和图；设置移入抽屉面板
view-full-run = 完整运行
    .title = 在每幅图上显示整个运行（也可双击图或按 Escape）
view-fit = 按启动暂态之后的数据调整 y 轴
# $ms 是启动暂态结束的时刻，单位为毫秒（8.5）。
view-fit-from = 按启动暂态之后的数据调整 y 轴（t ≥ { $ms } ms）
view-fit-why = 为何取这一时刻？
# $reason 是核心对启动暂态在何处结束的说明。
view-transient-reason = 启动暂态：{ $reason }。
figures-all = 全部指标
figures-fewer = 精简指标
figures-strip =
    .aria-label = 本次运行的指标
plots-hint = 在图上拖选即可同时放大所有图；双击、按 Escape 或“完整运行”可回到整个运行。图例显示光标所在采样点的记录值；点击图即可查看该时刻的每一项。

## 固定的运行及其叠加图（“轨迹”选项卡）

pins-pin = 固定此次运行
# 叠加图所比较的量的菜单标签。
pins-overlay = 叠加
pins-column-omega = 转速 ω
pins-column-omega-hat = 估计转速 ω̂
pins-column-flux = 磁链 |φ|
pins-column-voltage = 电压 u_sa
pins-unpin = 取消固定
# 列表中的一个固定运行：$n 是其编号（1），$legend 是其设置与当前运行的不同之处（k1=600）。
pins-item = 固定运行 { $n }：{ $legend }
# 叠加图图例中固定运行的名称；$n 是其编号（1）。
pins-name = 固定运行 { $n }
# 叠加图图例中的当前运行。
pins-current = 当前
# 叠加图图例中当前运行与固定运行 $n 之差。
pins-difference = 当前 − 固定运行 { $n }
# 叠加图的标题；$column 是所比较的量，与叠加菜单中的名称相同（转速 ω）。
pins-overlay-title = { $column }：当前运行与固定的运行
pins-difference-title = { $column }：当前 − 固定运行
# $n 是正在运行的固定运行（2），$count 是总数（3），$percent 是其完成的百分比（45）。
pins-status-running = 正在运行固定运行 { $n }（共 { $count } 个）：{ $percent }%
pins-status-done = 已固定
pins-status-cancelled = 固定已取消
# $length 是地址中固定运行部分的字符数，$max 是其允许的最大值。
pins-link-too-long = 地址中的固定运行未运行：共 { $length } 个字符，超过固定运行片段允许的 { $max } 个。
# $pins 列出无法读取的固定运行，各加引号；$count 是其个数。
pins-link-malformed = 已忽略地址中格式错误的固定运行：{ $pins }。
# $sent 是已运行的固定运行数（5），$dropped 是地址中多出的个数。
pins-link-dropped = 只运行了地址中的前 { $sent } 个固定运行；其余 { $dropped } 个被略去。
# 无法固定的运行：列表中的第一项（其余各项用 pins-rejected-next，以分号分隔）。
# $scenario 是其场景，$reason 是原因。
pins-rejected-first = 无法固定 { $scenario }：{ $reason }
pins-rejected-next = 无法固定 { $scenario }：{ $reason }
# 列出无法固定的运行的句子；$list 包含它们（pins-rejected-first、pins-rejected-next）。
pins-rejected = { $list }。
# 运行未被固定的原因：固定在其开始之前或运行期间被取消。
pins-reason-unrun = 未运行：固定已取消
pins-reason-cancelled = 已取消

## 消息中的列表

# 只列出前几项的列表；$list 是这几项，$count 是其余项数。
list-more = { $list } … 另有 { $count } 项

## 运行的状态行和消息

# $samples 是本次运行要计算的采样点数。
run-status-starting = 正在运行 { $samples } 个采样点…
run-status-progress = 正在运行：{ $total } 个采样点中已完成 { $done } 个
# $ms 是运行所用的时间，单位为毫秒。
run-status-done = { $rows } 个采样点，用时 { $ms } ms
run-status-ran-away = 失控：{ $rows } 个采样点，用时 { $ms } ms
run-status-stopped = 在 { $rows } 个采样点后停止
# $percent 是运行已完成的百分比（45）。
run-status-cancelled = 已取消（完成 { $percent }%）
run-status-worker-failed = 已停止：仿真工作线程失败
# $reason 是核心对运行停止原因的说明；$rows 是停止前计算的采样点数。
run-stopped-early = 运行提前停止：{ $reason }。图中显示停止前的 { $rows } 个采样点。
# $warning 是核心说明本次运行失控的句子。
run-ran-away = { $warning } 图中显示的是电机的实际情况。
run-worker-not-started = 仿真工作线程无法启动（{ $reason }）。请重新加载页面后再试。
run-worker-failed = 仿真工作线程失败（{ $reason }），已重新启动；请按“运行”重试。
# $pins 列出各固定运行的场景，以分号分隔。
run-worker-failed-pins = 仿真工作线程失败（{ $reason }），已重新启动；请按“运行”重试。固定的运行已被丢弃：{ $pins }。
# $language 是所请求语言的代码（de）。
page-language-failed = 页面无法载入 { $language } 语言的文字（{ $reason }）：现以英文显示。
page-messages-failed = 页面其余的文本无法加载（{ $reason }）。工具、课程和详解需要这些文本：使用其中任何一项时会重新尝试加载。
page-challenge-tools-failed = 无法载入“挑战”选项卡的出题与评分功能：{ $reason }。请重新打开该选项卡以重试。
page-lesson-map-failed = 未能读取本课的误差图：{ $reason }。
# $lesson 是地址所请求的课名；$lessons 列出各课的名称。
page-no-lesson = 没有名为“{ $lesson }”的课。可用的课：{ $lessons }。
# 课程链接无法与本课的运行比较的原因：它们补全课程面板中的句子
# “此链接带有自己的设置，……：……”。
lesson-differences-refused = 核心拒绝了其中一部分（{ $reason }）
lesson-differences-uncompared = 无法将它们与本课的运行比较

## 仿真工作线程失败的原因（上述消息中的 $reason）

worker-unknown-error = 未知错误
worker-unreadable = 无法读取它发来的一条消息
# $error 是浏览器的错误；$panic 是核心自己的消息。
worker-crash-panic = { $error }；Rust panic：{ $panic }
worker-crash-memory = { $error }；很可能是核心内存不足
# 分析所用线程池中的一个工作线程失败；$reason 说明原因。
pool-worker-failed = 一个工作线程失败（{ $reason }）
pool-worker-failed-restart = 一个工作线程失败（{ $reason }）；下次运行将启动新的工作线程
# $reason 是浏览器的错误。
worker-tools-not-loaded = 无法载入工具（{ $reason }）：请检查网络连接后重试。
# $reason 是核心的错误。
compare-failed = 比较失败：{ $reason }
compare-running = 正在运行两种预测器…

## 导出

export-csv-starting = 正在导出 CSV…
export-csv-progress = 正在导出 CSV：{ $total } 行中已完成 { $rows } 行
export-csv-done = CSV 已导出：{ $total } 行
export-csv-cancelled = CSV 导出已取消
export-csv-cancelled-by-run = CSV 导出已取消：新的运行已开始。
export-csv-stopped = CSV 导出已停止
export-csv-failed-status = CSV 导出失败
# $reason 是核心的错误，或 export-csv-gone。
export-csv-failed = CSV 导出失败：{ $reason }。
export-csv-gone = 工作线程已不再保存此次运行；请重新运行
# $megabytes 是浏览器已保存的 CSV 大小；$error 是浏览器错误的名称；
# $command 是导出此次运行的命令行（不翻译）。
export-csv-refused = 浏览器拒绝保存超过 { $megabytes } MB 的 CSV（{ $error }）。请改用命令行导出此次运行：{ $command }
export-png-not-ready = 这些图仍在绘制中；请稍后再导出。

## 分享

share-link-copied = 链接已复制：它能逐位复现此次运行。
# $link 是页面的地址。
share-copy-this-link = 请复制此链接：{ $link }
# 嵌入框架的标题，供屏幕阅读器朗读：$preset 是预设名，$plots 是各图的 id（speed, flux）。
share-embed-title = IM Lab：{ $preset }，{ $plots }
# $plots 列出各图的 id（speed, flux）；$count 是其个数。
share-embed-copied =
    嵌入代码已复制：此次运行的 { $plots } { $count ->
       *[other] 图
    }（“轨迹”选项卡中当前可见的图）。可将其粘贴到幻灯片或课程页面中。
# $code 是要复制的 HTML 代码。
share-embed-copy-this =
    请复制此嵌入代码，它显示此次运行的 { $plots } { $count ->
       *[other] 图
    }（“轨迹”选项卡中当前可见的图）：{ $code }
# $names 列出地址所请求的未知图 id，各加引号，$count 是其个数；
# $shown 是改为显示的图；$plots 是所有图的 id。
embed-unknown-plots = 没有名为 { $names } 的图；改为显示 { $shown }。可用的图：{ $plots }。

## 属于较早场景（而非当前设置）的结果（$scenario 即该场景）


## 某一步的自定义控制律（设置表单和设计详解）

# $step 是步骤编号（1 至 4）；v{ $step } 是其控制律的名称（v1）。
law-paper-default = 尚未编写自己的控制律：这一步运行论文的 v{ $step }。

## 设置表单

settings-group-reference = 参考值
settings-group-controller = 控制器：反步控制或经典 IFOC
settings-group-gains = 反步控制增益
settings-group-observer = 观测器（EKF）
settings-group-noise = 噪声与种子
settings-group-plant = 被控对象：仿真的电机
settings-group-model = 模型：EKF 和控制器所假设的
settings-group-load = 未知负载：阶跃或点表
settings-group-limits = 电压限幅（矩形）、额定电流、时长与时序
settings-group-drive = 驱动：计算延时、逆变器限幅与 PWM
settings-group-law = 反步控制各步的自定义控制律（为空：用论文的）
# 字段允许的取值，显示在字段下方及其提示中（settings-allowed）。
settings-allowed-formula = 由设计详解中“写出这一步”所列名称构成的公式；为空：论文的控制律
# $min 和 $max 是最小值和最大值（$max 带有字段的单位：20 s），$op 是 < 或 ≤，
# $key 是字段的键（duration）。
settings-allowed-range = { $min } { $op } { $key } ≤ { $max }
# 点表：至多 $points 个点；$min 和 $max 为取值的上下界（$max 带单位）。
settings-allowed-table = 至多 { $points } 个点 t:value，例如 0:0,0.1:100，时间从 0 起递增；取值从 { $min } 到 { $max }
settings-allowed-whole = { $min } { $op } { $key } ≤ { $max }，整数
# $values 是字段允许的取值（settings-allowed-range，或其选项：euler | rk4）。
settings-allowed = 允许：{ $values }
# $list 包含核心给出的各项原因，以分号分隔。
settings-link-rejected = 地址中的部分设置被拒绝，已保留为预设的值：{ $list }。
# $preset 是改为显示的预设。
settings-link-refused = 地址中的场景被拒绝：{ $reason }。改为显示 { $preset }。
# $description 是核心对该预设的描述；$fields 列出被修改的设置的键（k1, duration）。
settings-preset-changed = 预设 { $preset }：{ $description }。此次运行修改了 { $fields }，因此预设描述中关于其运行的说法不一定适用于此次运行。
settings-idle = { $changed } 被忽略的设置：{ $idle }。
settings-idle-separator = {"；"}

## 指标栏与关键指标

# 以电机额定电流的倍数表示的电流：$value 是电流（20.33 A），
# $ratio 是倍数（5.08），$rated 是额定电流（4）。
figures-to-rated = { $value }（额定 { $rated } A 的 { $ratio } 倍）
# 平均 NIS（$value）及其 95% 区间，从 $low 到 $high。
figures-nis-inside = { $value }（95% 区间 { $low }–{ $high }：在区间内）
figures-nis-outside = { $value }（95% 区间 { $low }–{ $high }：在区间外）
# 指标的提示：$value 是带单位的精确值，$window 是核心对其所覆盖运行区段的说明。
figures-exact = 精确值：{ $value }；{ $window }
# 运行未达到的指标的提示：$reason 是核心对此的说明。
figures-no-value = 无数值：{ $reason }；{ $window }
# 最终值在运行结束时是否已稳定。$rate、$scatter、$tolerance 和 $to-go
# 是带单位的值（0.5 rad/s）。
figures-trend-settled = 运行结束时已稳定
figures-trend-ran-away = 运行失控：不是最终值
figures-trend-drifting = 随 EKF 对负载或 R_r 的随机游走估计而漂移：运行更长时间，结束值会不同
figures-trend-fluctuating = 波动幅度 ±{ $scatter }：最后一个采样点不是最终值
figures-trend-changing = 仍在变化：结束时每秒变化 { $rate }；请延长运行
figures-trend-changing-to-go = 仍在变化：结束时每秒变化 { $rate }；请延长运行（约还差 { $to-go }）
# 最终值趋势的提示：$ms 是拟合直线所用的运行末段长度。
figures-trend-fit = 对最后 { $ms } ms 拟合的直线：每秒 { $rate }，采样点在其周围的散布为 { $scatter }；“已稳定”指该直线的变化在 { $tolerance } 以内，且四倍散布也不超出此范围
figures-trend-fit-approach = 对最后 { $ms } ms 拟合的直线：每秒 { $rate }，采样点在其周围的散布为 { $scatter }；最后三个十分之一时段的均值趋近于相距 { $to-go } 的一个值；“已稳定”指该直线的变化在 { $tolerance } 以内，且四倍散布也不超出此范围
# 关键指标行：$value 是带单位的值；$ratio 是额定电流的倍数。
figures-key-peak = |i_s| 峰值 { $value }（额定值的 { $ratio } 倍）
figures-key-final =
    最终 ω − ω_d { $value }（{ $trend ->
        [settled] 已稳定
        [changing] 仍在变化
        [drifting] 漂移中
        [fluctuating] 波动中
       *[ran-away] 失控
    }）
figures-key-nis-inside = 平均 NIS { $value }（在其 95% 区间内）
figures-key-nis-outside = 平均 NIS { $value }（在其 95% 区间外）
# 各图的文字替代内容包含这些指标：$figures 列出它们，以分号分隔。
figures-caption = 此次运行的指标：{ $figures }。

## 图

plot-speed = 转子转速
plot-speed-reference = ω_d 参考值
plot-speed-estimated = ω̂ 估计值
plot-speed-true = ω 真实值
plot-speed-error = 转速跟踪误差 ω − ω_d
plot-flux = 转子磁链幅值
plot-flux-target = √ψ_d 目标值
plot-flux-estimated = |φ̂| 估计值
plot-flux-true = |φ| 真实值
plot-current = 定子电流
plot-current-a-estimated = î_sa 估计值
plot-current-b-estimated = î_sb 估计值
plot-current-a-true = i_sa 真实值
plot-current-b-true = i_sb 真实值
plot-voltage = 施加的定子电压（限幅后）
# 电压图上的电压限幅线。
plot-voltage-limit-high = +限幅
plot-voltage-limit-low = −限幅
plot-z13 = 跟踪误差
# “右轴”：该曲线按图右侧的坐标轴读数。
plot-z13-flux = z3 = |φ̂|² − ψ_d（Wb²，右轴）
plot-z24 = 虚拟控制误差
plot-z24-torque = z2 转矩误差（rad/s²）
plot-z24-flux = z4 磁链变化率误差（Wb²/s，右轴）
plot-est = 估计误差
plot-est-flux = |φ| − |φ̂|（Wb，右轴）
# 由经典 IFOC 驱动电机时，反步控制图的标题（$title）。
plot-not-driving = { $title }（仅供比较，未驱动电机）
# 图的文字替代内容：$title 是其标题，$unit 是坐标轴的单位，$signals 是各曲线的名称。
plot-caption = { $title }，单位为 { $unit }，横轴为时间 t（s）。信号：{ $signals }。
plot-caption-two-axes = { $title }，单位为 { $unit }（左轴）和 { $unit2 }（右轴），横轴为时间 t（s）。信号：{ $signals }。
plot-caption-keys = 聚焦此图后，可用方向键逐个采样点查看运行（按住 Shift：每次移动窗口的 1%）。

## “分析”选项卡


## “课程”选项卡


## “挑战”选项卡


## The challenge panel's controls, built with the page

challenge-progress =
    .aria-label = 已完成的挑战运行
challenge-cancel = 取消检查
challenge-copy = 复制提交链接
challenge-open-failed = 无法打开此挑战：{ $reason }。页面改为显示默认场景。
law-checking = 正在按设计的动态检查你的控制律…
law-verdict-failed = 无法计算对你的控制律的判定：{ $reason }
walkthrough-load-failed = 无法载入设计详解：请检查网络连接并重新加载页面。
lesson-panel =
    .aria-label = 课程
challenge-panel =
    .aria-label = 挑战
stale-back = 返回其场景
