# 核心关于设计挑战及其评分的消息：挑战链接或提交链接被拒绝的原因、任务的文字说明、对每项判据
# 的判定，以及全班评分。命令行界面按此文件的英文版输出；页面则使用读者的语言；成绩 CSV 中
# 为英文。键、字段、指标和设置（c=1、allow.FIELD、need.FIGURE=OP、seeds:A..B、try.FIELD、
# mean_nis、load.torque = 0）是链接自身的写法：保持原样。引用的输入保留其引号。

## 挑战链接或提交链接被拒绝

# $key 是链接的键（title、vary、try.k1…），$value 是其中的文字。
challenge-not-percent-encoded = 字段 '{ $key }' = '{ $value }'：不是有效的百分号编码 UTF-8
challenge-too-long = 挑战长 { $bytes } 字节，超过允许的 { $max } 字节（{ $kib } KiB）
# $names 列出各内置挑战的名称。
challenge-unknown = '{ $name }' 既不是挑战链接，也不是内置挑战（{ $names }）
challenge-unsupported-version = 字段 'c' = '{ $value }'：不支持的挑战版本，允许：{ $version }
# $fields 列出挑战链接可含的键。
challenge-unknown-key = 字段 '{ $key }' 不是挑战字段（{ $fields }）
challenge-missing = 缺少字段 '{ $key }'
# $name 是内置挑战的名称。
challenge-builtin-extra = 字段 '{ $key }' 不能跟在 challenge={ $name } 之后：内置挑战的链接只含 challenge=NAME 和学生的 try.FIELD 部分
# $stray 是 c= 之前多出的字符；$count 是其个数。
challenge-stray = 链接在 c={ $version } 之前有多余的{ $count ->
       *[other] 字符
    } '{ $stray }'：{ $count ->
       *[other] 请将其删除
    }
challenge-version-missing = 缺少字段 'c'（挑战以 c={ $version } 开头）
challenge-title-too-long = 字段 'title' 长 { $chars } 个字符，超过允许的 { $max } 个
# $error 说明基础场景被拒绝的原因（scenario-* 消息）。
challenge-bad-base = 字段 'base'：{ $error }
challenge-no-criteria = 没有判据：请至少添加一个 need.FIGURE=OP
challenge-too-many-criteria = 共 { $count } 项判据，超过允许的 { $max } 项
challenge-vary-unused = 字段 'vary'：没有判据用到这些变体（请在鲁棒列表 robust= 中写出判据的指标名称）
challenge-robust-without-vary = 字段 'robust'：没有变体可供检验鲁棒性（请添加 vary=）
# $key 是 allow.FIELD；$field 是它所指的场景字段。
challenge-allow-unknown-field = 字段 '{ $key }'：'{ $field }' 不是场景字段
challenge-allow-formula = 字段 '{ $key }' = '{ $value }'：允许某一步的控制律须写作 allow.{ $field }=formula
challenge-allow-range = 字段 '{ $key }' = '{ $value }'：应为 LO..HI，即两个数，且 LO ≤ HI
# $error 说明范围的某一端为何不是该字段的取值（scenario-* 消息）。
challenge-allow-refused = 字段 '{ $key }' = '{ $value }'：{ $error }
# $options 列出该字段的可选名称，以 | 分隔。
challenge-allow-choice = 字段 '{ $key }' = '{ $value }'：应为取自 { $options } 的互不相同的名称，以 | 分隔
# $key 是 need.FIGURE；$figures 列出判据可用的指标。
challenge-need-unknown-figure = 字段 '{ $key }'：'{ $figure }' 不是指标（{ $figures }）
challenge-need-band = 字段 '{ $key }' = 'band'：只有 mean_nis 有区间
challenge-need-op = 字段 '{ $key }' = '{ $value }'：应为 max:B、min:B、abs:B 或 band
challenge-need-no-load-step = 字段 '{ $key }'：基础场景没有负载阶跃（load.torque = 0，或改用了负载表）
challenge-vary-seeds = 字段 'vary' = '{ $value }'：应为 seeds:A..B，A、B 为整数，A ≤ B ≤ { $max_seed }，且至多 { $max } 个种子
challenge-vary-too-many = 字段 'vary'：共 { $count } 个变体，超过允许的 { $max } 个
# $number 从 1 起数变体；$error 说明它有何问题（scenario-* 消息）。
challenge-vary-variant-refused = 字段 'vary'，第 { $number } 个变体：{ $error }
challenge-vary-variant-empty = 字段 'vary'，第 { $number } 个变体为空
# $overrides 是该变体的设置（seed=2）；$error 说明其为何无法应用。
challenge-variant-refused = 变体 '{ $overrides }'：{ $error }
# $value 是 robust= 列表，$figure 是其中不属于任何判据的名称。
challenge-robust-unknown = 字段 'robust' = '{ $value }'：'{ $figure }' 不是任何判据的指标（或被列出了两次）
challenge-is-submission = 字段 'try.{ $key }'：这是提交链接，而不是挑战（请按其挑战为它评分）
challenge-another = 该提交属于另一个挑战（其挑战部分不同）
challenge-try-not-allowed = 不允许修改字段 '{ $field }'
challenge-try-not-number = 字段 'try.{ $field }' = '{ $value }'：不是数字
# $setting 是学生的设置（k1=6000），$range 是允许的范围（300..5000）。
challenge-try-outside = { $setting } 超出 { $range }
# $options 列出允许的名称，以 | 分隔。
challenge-try-not-option = { $setting } 不是 { $options } 之一
challenge-compose-range-and-options = 字段 '{ $key }'：请给出 LO 和 HI（范围）或选项（可选值），不能同时给出
challenge-judge-runs = 挑战有 { $runs } 次运行（标称运行及 { $variants } 个变体），却测得 { $measured } 次

## 任务的文字说明

challenge-untitled = 设计挑战
# 挑战的标题，按出题者所写。
challenge-title = { $title }
# $base 是场景字符串。
challenge-brief-start = 从场景 { $base } 出发
challenge-brief-nothing-allowed = 不能修改任何设置：基础场景按原样判定。
challenge-brief-allowed = 你只能修改：
# 学生可修改的一个字段：$field 是其名称（已补齐成一列），$range 是允许的取值
# （challenge-brief-range、-one-of 或 -formula 消息），$now 是基础场景的值，$doc 是字段的说明。
challenge-brief-allow = { $field } { $range }（当前 { $now }）— { $doc }
# $hi 带有单位（若有）。
challenge-brief-range = { $lo } 至 { $hi }
# $options 列出各名称。
challenge-brief-one-of = { $options } 之一
challenge-brief-formula = 自己编写的公式
challenge-brief-formula-unit = 自己编写的公式，单位为 { $unit }
challenge-brief-needs = 你的设计必须满足：
# 一项判据：$number 从 1 起数，$label 是指标的说明，$figure 是其名称，$bound 是
# challenge-brief-at-most、-at-least、-within 或 -band 消息；最终值须已稳定时 $settled 为 yes；
# 须在每个变体上也成立时 $robust 为 yes。
challenge-brief-need = { $number }. { $label }（{ $figure }）：{ $bound }{ $settled ->
        [yes] ，且在运行结束时已稳定
       *[no] {""}
    }{ $robust ->
        [yes] ，标称运行和每个变体均须满足
       *[no] {""}
    }
# $bound 带有单位（若有）。
challenge-brief-at-most = 至多 { $bound }
challenge-brief-at-least = 至少 { $bound }
challenge-brief-within = 在 ±{ $bound } 以内
challenge-brief-band = 在一致滤波器的 95% 区间内（mean_nis_low 至 mean_nis_high）
# $first 和 $last 是第一个和最后一个噪声种子（seed=2…）。
challenge-brief-variants-seeds = 变体（叠加在你的设置之上；以最差运行为准）：噪声种子 { $first } 至 { $last }
# $overrides 列出各变体的设置，以分号分隔。
challenge-brief-variants = 变体（叠加在你的设置之上；以最差运行为准）：{ $overrides }
challenge-brief-load-recovery = 负载恢复时间：从负载阶跃（t = { $time } s）起，直到 |ω − ω_d| 保持在 max(阶跃时 |ω_d| 的 1%, 0.5 rad/s) 以内直至运行结束所经历的时间（此处为 { $band } rad/s，ω_d = { $speed } rad/s）；若结束时仍在此范围之外，则为未恢复。
challenge-brief-settled = 最终值只有在已稳定时才算数：在运行的最后十分之一时段内仍在变化的值判为未通过。
# 数值及其单位："0.004 s"。
challenge-quantity = { $value } { $unit }

## 判据的界限及未通过的原因

# $bound 带有单位（若有）："≤ 0.004 s"。
challenge-bound-max = ≤ { $bound }
challenge-bound-min = ≥ { $bound }
challenge-bound-abs = |·| ≤ { $bound }
challenge-bound-band = 在其 95% 区间内
# $failure 说明运行失败的原因（在仿真的消息翻译之前为英文）。
challenge-run-unfinished = 运行未完成
challenge-reason-run-failed = 运行失败：{ $failure }
# $cause 说明该指标为何不是数值（在运行报告翻译之前为英文）。
challenge-reason-not-finite = { $cause }
challenge-reason-before-load-step = 未测得：运行在负载阶跃之前结束
challenge-reason-not-measured = 此次运行未测得（例如阶跃响应始终未稳定在 2% 以内）
challenge-reason-no-band = 未测得：此次运行没有 NIS 区间
challenge-reason-above-bound = 高于界限
challenge-reason-below-bound = 低于界限
challenge-reason-beyond-bound = 超出界限
challenge-reason-below-band = 低于区间
challenge-reason-above-band = 高于区间
challenge-reason-not-recovered = 运行结束时仍未恢复
challenge-reason-still-changing = 仍在变化

## 全班评分：每份提交的状态（成绩 CSV 中亦然）及班级文件

grade-row-ok = 正常
# $reason 说明该链接为何不是格式正确的提交。
grade-row-malformed = 格式错误：{ $reason }
# $reason 指出学生设置的不允许修改或超出范围的字段。
grade-row-refused = 被拒绝：{ $reason }
grade-row-another = 另一个挑战
# $reason 说明运行失败的原因（在仿真的消息翻译之前为英文）。
grade-row-run-failed = 运行失败：{ $reason }
grade-internal-error = 内部错误
# $encoding 是读取该文件所用编码的名称（UTF-8、windows-1252…）。
grade-line-undecoded = 第 { $line } 行不是有效的 { $encoding }
grade-line-unclosed = 第 { $line } 行：带引号的字段到文件末尾仍未闭合
grade-line-fields = 第 { $line } 行有 { $fields } 个字段，而表头有 { $header } 个
grade-no-link = 没有链接
# $error 说明挑战被拒绝的原因。
grade-challenge-refused = 挑战：{ $error }
grade-file-not-text = 该文件不是文本（含有 NUL 字节：是电子表格还是文档？）；请将其另存为每行一个链接的文本文件，或存为 CSV
grade-file-utf16 = 该文件是不带字节顺序标记的 UTF-16；请将其另存为 UTF-8
grade-file-header-undecoded = 第 { $line } 行（CSV 表头）不是有效的 { $encoding }
# $columns 列出文件的各列标题，各加引号。
grade-file-no-link-column = 此 CSV 导出中没有链接列（其各列：{ $columns }）；请将链接列的标题设为 'link'
grade-file-links-everywhere = { $columns } 各列都含有链接；请将要评分的那一列的标题设为 'link'
grade-file-link-headers = { $columns } 各列的标题都表明是链接；请只保留一列

## 继续中断的评分（imlab grade --resume）：其先前的输出为何被拒绝

grade-resume-not-utf8 = 它不是 UTF-8 文本，因此不是这个班级的成绩
# $header 是此次评分写出的 CSV 表头行。
grade-resume-header = 它的第一行不是此次评分的表头 '{ $header }'：它保存的是另一个挑战或另一个班级文件的成绩
grade-resume-too-many-rows = 它的行数多于班级文件的 { $rows } 份提交
grade-resume-row = 它的第 { $row } 行与班级文件第 { $line } 行（'{ $link }'）不对应：它保存的是另一个班级文件的成绩
# $what 是 grade-kept-* 消息之一。
grade-kept-differs = 它的第 { $row } 行（班级文件第 { $line } 行）与重新评分的结果不同：{ $what }；它在评分后被修改过，或是由另一版本的 imlab 评分的
# $column 是 CSV 列名（status、settling_time_pass…）。
grade-kept-cell = 其 { $column } 为 '{ $found }'，而不是 '{ $expected }'
grade-kept-extra = 其最后一列之后还有 '{ $extra }'
grade-kept-short = 缺少从 { $column } 起的各列
