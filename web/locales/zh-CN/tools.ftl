# 分析与挑战工具的文字：“分析”选项卡（扫描、多种子区间带、模型误差图）、学生看到的挑战面板，
# 以及教师使用的“挑战”选项卡（出题、出题检查、全班评分）。

## 频率响应扫描：伯德图和表格（web/analysis/analysis.js）

sweep-plot-magnitude = ω/ω_d 的幅值
sweep-plot-phase = ω 相对于 ω_d 的相位
sweep-axis-degrees = 度
sweep-series-unsettled = { $variant }，未稳定
sweep-unsettled =
    { $count ->
       *[other] 有 { $count } 个点未稳定（空心标记）：带宽和 200 Hz 处的相位从不取自这些点。运行更长时间可能使其稳定。
    }
sweep-unsettled-point = { $variant }，{ $frequency }：{ $reason }
sweep-hz = { $value } Hz
sweep-degrees = { $value } °
sweep-head-variant = 方案
sweep-head-bandwidth = −3 dB 带宽
sweep-head-phase = 200 Hz 处的相位
sweep-head-saturation = 最严重饱和
sweep-head-failed = 失败点
sweep-head-unsettled = 未稳定点
sweep-head-peak = |i_s| 峰值 (A)
sweep-bandwidth-unsettled = 未给出：它将取决于一个未稳定的点
sweep-bandwidth-below = 低于最低频率
sweep-not-reached = 在频率网格内未达到
sweep-phase-not-reached-settled = 已稳定的点均未达到
sweep-unsettled-cell = { $count }：{ $frequencies }
sweep-peak-none = 未测得
sweep-peak = { $peak }（额定 { $rated }）
sweep-peak-over = { $peak }（额定 { $rated }）；在 { $count } 个频率点超过额定值：{ $frequencies }

## 多种子区间带：图（web/analysis/analysis.js）

seeds-plot-error = 各种子下的转速误差 ω − ω_d（均值、最小值、最大值）
seeds-plot-estimate = 各种子下的估计误差 ω − ω̂（均值、最小值、最大值）
seeds-series-mean = 均值
seeds-series-min = 最小值
seeds-series-max = 最大值

## 频率响应扫描：表单的运行、状态行和链接（web/analysis/sweeps.js）

sweep-workers-invalid = workers = { $value }：应为 1 至 8 的整数。
sweep-status-checking = 正在检查扫描…
sweep-refused = { $reason }。
sweep-not-run = 扫描未运行：设置无效或在此处不允许；原因见页面顶部的信息。
sweep-status-running = 正在扫描…
sweep-status-done =
    { $workers ->
       *[other] { $variants } × { $points } 次运行，用时 { $ms } ms，使用 { $workers } 个工作线程。
    }
sweep-status-cancelled = 扫描已取消。
sweep-status-failed = 扫描失败：{ $reason }
sweep-link-refused = 地址中的扫描（{ $link }）未运行：{ $reason }。

## 多种子运行：表单的运行和状态行（web/analysis/seeds.js）

seeds-count-invalid = seeds = { $value }：种子数应为 1 至 1000 的整数。
seeds-not-run = 多种子运行未进行：设置无效或在此处不允许；原因见页面顶部的信息。
seeds-status-starting = 正在运行多种子…
seeds-status-running = 正在运行多种子：{ $percent }%
seeds-status-done = { $seeds } 个种子中有 { $runs } 个已完成（种子 { $first } 至 { $last }）。
seeds-status-cancelled = 多种子运行已取消。
seeds-status-failed = 多种子运行失败：{ $reason }

## 模型误差图：运行和状态行（web/analysis/robust.js）

map-status-starting = 正在运行 { $cells } 个格子 × { $seeds } 个种子…
map-status-running = 正在运行误差图：{ $total } 次运行中已完成 { $done } 次。
map-refused = 误差图未运行：{ $reason }。
map-not-run = 误差图未运行：设置无效或在此处不允许；原因见页面顶部的信息。
map-failed = 误差图运行失败：{ $reason }
map-status-cancelled = 误差图已取消：{ $cells } 个格子中有 { $finished } 个已完成并显示；其余未运行。
map-status-done = { $cells } 个格子 × { $seeds } 个种子（{ $first }–{ $last }），用时 { $seconds } s。
map-link-refused = 地址中的误差图（{ $link }）未运行：{ $reason }。

## 模型误差图：沿一个轴的图（web/analysis/map-plot.js）

map-plot-title = { $figure }（各种子）：中位数及最小–最大区间带
map-series-min = 最小值
map-series-median = 中位数
map-series-max = 最大值
map-gap = { $value }（{ $runs } 个种子中 { $ranAway } 个失控）
map-gap-percent = { $value }%（{ $runs } 个种子中 { $ranAway } 个失控）
map-gaps = 未绘出，因为部分种子在这些取值处失控：{ $cells }。

## 模型误差图：表格及其图例（web/analysis/map-table.js、map-colours.js）

map-figure-unit = { $figure }（{ $unit }）
map-cell-not-run = 未运行
map-cell-title = { $scenario }：{ $runs } 个种子中 { $ranAway } 个失控，{ $inconsistent } 个不一致，{ $overRating } 个超过额定电流，{ $unsettled } 个在运行结束时转速误差尚未稳定；{ $figure } 为 { $min } 至 { $max }
map-grid-corner = { $rows } ↓ / { $columns } →
map-head-median = 中位数
map-head-range = 最小 – 最大
map-range = { $min } – { $max }
map-key = { $figure }，取未失控种子的中位数（{ $seeds } 个种子）；颜色：{ $colours }。✕ k/N：该运行在 N 个种子中的 k 个上失控（该运行自己的页面如此报告，或其发散），从不按数值着色；⚠ EKF 不一致；I↑ k/H：在成立的 H 个种子中，有 k 个在启动之后所需电流超过电机的额定电流；~ k/H：有 k 个在结束时转速误差尚未稳定（两者均加轮廓，并按其中位数着色）。点击格子即可运行它（种子 { $seed }）。
map-scale-diverging = 蓝色 −{ $max } 经白色 0 到红色 { $max }
map-scale-log = 对数刻度，从浅色 { $min } 到深色 { $max }
map-scale-linear = 线性刻度，从浅色 { $min } 到深色 { $max }
map-scale-none = 无

## 挑战面板：学生看到的挑战链接（web/challenge/challenge.js）

challenge-heading = 挑战
challenge-link-rejected = 此挑战链接被拒绝：{ $reason }。页面改为显示默认场景。
challenge-submission-another = 此提交链接属于另一个挑战（其挑战部分被改动过）：未评分。
challenge-submission-refused = 此提交链接未被接受：{ $reason }。未评分；任务从其基础设置开始。
challenge-submission-rejected = 此提交链接被拒绝：{ $reason }。未评分；任务从其基础设置开始。
challenge-run = 运行并检查
challenge-settings = 你的设置
challenge-settings-hint = 只能修改 { $fields }；其他设置已被挑战锁定。
challenge-checklist = 检查清单
challenge-task = 完整任务
challenge-verdict-pending = 尚未检查：正在计算第一次运行。
challenge-need-pending = { $label }（{ $figure }）：尚未检查
challenge-verdict-link-refused = ✗ 未评分：链接中的设置未被接受（见上文）。请修改允许的设置后运行。
challenge-verdict-cancelled = ✗ 检查已取消：未评分。请重新运行以检查。
challenge-verdict-failed = ✗ 检查失败：{ $reason }。未评分。
challenge-verdict-edited = 这不是内置挑战 { $name }：其条件已被改动。
challenge-verdict-rerun = 屏幕上的运行不是评分所用的运行（某项锁定的设置不同）：已按挑战的设置和你允许修改的设置重新进行了标称运行。
challenge-checking =
    正在检查：{ $runs ->
       *[other] { $runs } 次运行
    }中已完成 { $done } 次（标称运行及 { $variants ->
       *[other] { $variants } 个变体
    }）…
challenge-refusal-not-run = 你的设置不是有效答案：{ $reason }。未运行。
challenge-verdict-not-run = ✗ 未运行。你的设置不是有效答案：{ $reason }。
challenge-refusal-not-graded = 你的设置不是有效答案：{ $reason }。未评分。
challenge-verdict-not-graded = ✗ 未评分。你的设置不是有效答案：{ $reason }。
challenge-copied = 提交链接已复制：它能逐位复现这些运行。
challenge-copy-by-hand = 请复制此提交链接：{ $url }

## 挑战面板：检查清单及其控件（web/challenge/checklist.js）

checklist-not-measured = 未测得
checklist-never = 从未（∞）
checklist-value-unit = { $value } { $unit }
checklist-passed =
    { $criteria ->
       *[other] ✓ 通过：{ $criteria } 项判据全部满足。
    }
checklist-passed-variants =
    { $criteria ->
       *[other] ✓ 通过：{ $criteria } 项判据全部满足（标称运行及 { $variants ->
            *[other] { $variants } 个变体
        }）。
    }
checklist-failed = ✗ 未通过：{ $criteria } 项判据中满足 { $met } 项。
checklist-failed-variants =
    ✗ 未通过：{ $criteria } 项判据中满足 { $met } 项（标称运行及 { $variants ->
       *[other] { $variants } 个变体
    }）。
checklist-pass = ✓ 通过
checklist-fail = ✗ 未通过
checklist-criterion = { $label }：{ $value }，要求 { $bound }
checklist-criterion-worst = { $label }：{ $value }，要求 { $bound }（最差运行：{ $run }）
checklist-reason = — { $reason }

## 挑战面板：允许修改的设置的旋钮（web/challenge/knobs.js）

challenge-knob-doc = { $doc }（{ $unit }）
challenge-allowed-choice = 允许：{ $options } 之一
challenge-allowed-formula = 允许：自己编写的公式（{ $unit }；可用名称见设计详解中的“写出这一步”）
challenge-allowed-range = 允许：{ $lo } 至 { $hi }
challenge-allowed-range-unit = 允许：{ $lo } 至 { $hi } { $unit }

## 挑战面板：标题栏，挑战的来源（web/challenge/origin.js）

challenge-kind = 挑战
challenge-origin-builtin = 内置挑战
challenge-origin-mine = 由你在此浏览器中设置：此浏览器正是按原样编写了这一挑战（界限和标题均未改动）
challenge-origin-other = 不是你在此浏览器中设置的挑战
challenge-origin-unknown = 此浏览器没有保存它所编写的挑战的记录
challenge-fingerprint = 指纹
challenge-edited = 已改动：此链接带有内置挑战 { $name } 的标题，但条件与之不同。它按其实际条件评分，而不是作为 { $name } 评分。

## “课程”选项卡中的内置挑战（web/challenge/builtins.js）

builtins-open = 打开挑战 { $name }
builtins-failed = 无法列出内置挑战。

## “挑战”选项卡：出题（web/challenge/challenge-compose.js）

compose-intro = 挑战从设置中的场景（即其基础）出发；学生只能在各自的范围内修改此处列出的字段，每项判据都成立即为通过。请先设好场景并运行：判据会根据本次运行的指标预先填好，比本次运行严格 20%。
compose-base = 基础：
compose-title = 标题
compose-title-default = 挑战：预设 { $preset }
compose-make = 生成挑战链接
compose-no-run = 此场景没有已完成的运行可供提取指标：请先运行，然后再按“按当前场景填写”。
compose-invalid = 挑战无效：{ $reason }
compose-link = 挑战链接
compose-kept = 此浏览器会记录它编写了这一挑战：该链接在此处打开时显示“由你在此浏览器中设置”；改动了界限或标题的副本则不会。
compose-not-kept = 此浏览器不保存它所编写的挑战的记录（此处无法使用其存储或 Web Crypto）：该链接在此处打开时，无法表明是你设置的。
compose-copy-link = 复制挑战链接
compose-link-copied = 挑战链接已复制。
compose-link-not-copied = 请选中上方的挑战链接并复制。
compose-open = 以学生身份打开
compose-brief = 任务的文字说明（用于幻灯片或课程页面）
compose-copy-brief = 复制任务
compose-brief-copied = 任务已复制。
compose-brief-not-copied = 请选中上方的任务并复制。

## “挑战”选项卡：出题的各行（web/challenge/compose-rows.js）

compose-allow-legend = 学生可修改的字段
compose-field = 字段
compose-field-option = { $field } — { $doc }
compose-add = 添加
compose-remove = 移除
    .aria-label = 移除 { $field }
compose-allow-formula = 学生自己编写的公式（{ $unit }）
compose-allow-choices = { $field }：可选值（a|b）
compose-allow-from = 从
compose-allow-to = 至
compose-allow-now-unit = { $unit }（当前 { $value }）
compose-allow-now = （当前 { $value }）
compose-need-legend = 判据：本次运行的指标
compose-need-hint = 勾选“所有运行”后，该判据在每个变体上也须成立（以最差运行为准）。
compose-need = { $label }（{ $figure }）
compose-need-now = { $label }（{ $figure }）— 当前 { $value }
compose-need-now-unit = { $label }（{ $figure }）— 当前 { $value } { $unit }
compose-need-op = { $figure }：界限类型
compose-need-bound = { $figure }：界限
compose-need-bound-unit = { $figure }：界限 { $unit }
compose-op-max = 至多
compose-op-min = 至少
compose-op-abs = |值| 至多
compose-op-band = 在其 95% 区间内
compose-bound-none = 无
compose-need-all-runs = 所有运行
compose-vary-legend = 鲁棒性变体（可选）
compose-vary = 变体：种子范围 seeds:A..B，或叠加在学生设置之上的设置，以 | 分隔
    .placeholder = seeds:2..10（种子）  或  model.j=0.016|model.j=0.024
compose-vary-seeds = 种子 2 至 10

## “挑战”选项卡：检查是否有设计能通过（web/challenge/compose-check.js）

compose-check-progress =
    .aria-label = 挑战检查：已完成的运行
compose-check-cancel = 取消检查
compose-check-starting = 正在检查允许范围内是否有能通过的设计…
compose-check-running =
    正在检查允许范围内是否有能通过的设计：{ $runs ->
       *[other] { $runs } 次运行
    }中已完成 { $done } 次（{ $designs ->
       *[other] { $designs } 个设计
    }）…
compose-check-cancelled = 检查已取消：尚不知道允许范围内是否有能通过的设计。请重新生成链接以进行检查。
compose-check-failed = 检查失败：{ $reason }。
compose-check-base-design = 基础设置，未改动任何字段
compose-check-failure = { $figure }：{ $value }，要求 { $bound }
compose-check-failure-changing = { $figure }：{ $value }，要求 { $bound }，仍在变化
compose-check-unmeasured = { $figure }：{ $reason }
compose-check-base-passes = 基础设置原样即可通过：学生不做任何修改也能通过。
compose-check-base-fails = 基础设置（未改动任何字段）未通过：{ $failures }。
compose-check-tried =
    检查在 { $runs ->
       *[other] { $runs } 次运行
    }中尝试了 { $designs ->
       *[other] { $designs } 个设计
    }（至多 { $budget } 次运行）：先试基础设置，再试改动字段最少的设计，从各范围的两端向内取值（数量允许时，试遍所有组合）。
compose-check-solvable = ✓ 允许范围内有能通过的设计：{ $design }（所试的 { $tried } 个设计中有 { $passing } 个通过）。
compose-check-unsolved = ✗ 所试的 { $tried } 个设计均未通过：界限可能无法达到；最接近的是 { $design }（{ $failures }）。

## “挑战”选项卡：全班评分（web/challenge/grade.js）

grade-refused = 未评分：{ $reason }。
grade-no-challenge = 请指定挑战：内置挑战的名称或挑战链接
grade-no-file = 请选择班级文件，或粘贴链接，每行一个
grade-no-submission = 文件中没有任何提交
grade-read-as = 班级文件按 { $encoding } 读取（它不是 UTF-8）。
grade-status-reading = 正在读取班级文件…
grade-status-grading = 正在为 { $total } 份提交评分…
grade-status-grading-kept = 正在为 { $total } 份提交评分，其中 { $kept } 份沿用上次的评分结果…
grade-count = 已评分 { $done } / { $total }
grade-status-done = 已评分 { $total } / { $total }：{ $passed } 份通过。
grade-not-stored = 浏览器的存储未能保存此次评分：请立即下载。
grade-status-cancelled-kept = 已取消：{ $total } 份中已评分 { $graded } 份，已保存在此浏览器中；按“评分”即可从该处继续。
grade-status-cancelled-lost = 已取消：{ $total } 份中已评分 { $graded } 份，未保存（浏览器的存储拒绝保存）。
grade-status-stopped-kept = 评分中止：{ $reason }。{ $total } 份中已评分 { $graded } 份，已保存在此浏览器中；按“评分”即可从该处继续。
grade-status-stopped-lost = 评分中止：{ $reason }。{ $total } 份中已评分 { $graded } 份，未保存（浏览器的存储拒绝保存）。
grade-status-cancelled-reading = 在读取班级文件时已取消：未对任何提交评分。
grade-downloaded-partial = 已按顺序下载 { $total } 行中的前 { $rows } 行：“评分”会从中断处继续，{ $command } 也可补全该文件。

## “挑战”选项卡：全班结果表（web/challenge/grade-table.js）

grade-pending = 尚未评分
grade-pass = ✓ 通过
grade-fail = ✗ 未通过
grade-head-line = 行
grade-head-verdict = 判定
grade-head-link = 链接
grade-value-reason = { $value }：{ $reason }
grade-worst-run = { $text }（最差运行：{ $run }）

motor-intro = 与 imlab motor 一样，由定子直流电阻、额定电压下的空载试验和堵转试验（IEEE Std 112）估计电机的等效电路，并指出哪些值是估计值。随后该电机同时作为被控对象和模型运行，并采用由它推导出的设计。每项试验为一组读数：线电压、线电流、输入功率和频率，以逗号分隔。
motor-rs = 每相定子电阻，直流试验
motor-no-load = 空载试验
motor-locked = 堵转试验
# NEMA 设计字母决定堵转漏抗在定子和转子之间的分配。
motor-nema = NEMA 设计字母
motor-rated = 铭牌：电压、频率、电流
motor-j = 转子转动惯量
motor-np = 极对数
motor-run-button = 估计等效电路
motor-example-button = 填入示例
motor-example-filled = 表单中是一台 2.2 kW、400 V 的电机，按实验室的记录方式填写：铭牌以及由其等效电路得到的读数（这是模拟的实验室，而非产品目录中的电机）。
motor-open = 用推导出的设计运行该电机
