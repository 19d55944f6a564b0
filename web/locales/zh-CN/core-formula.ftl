# The core's refusals of a formula, and why a law's distance from its designed dynamics is not a
# number: said as a link is read or a run ends, with the page's first messages.
# $reason 是下面的 formula-* 消息之一；$at 从 1 起数公式的字符。
formula-at = 第 { $at } 个字符处：{ $reason }
# $written 是输入的数。
formula-not-a-number = '{ $written }' 不是数字
formula-number-too-large = '{ $written }' 作为数字过大
# $char 是输入的字符。
formula-not-in-language = '{ $char }' 不属于公式语言（+ − * / ^、括号、名称、数字）
formula-division-by-zero = 除以零
formula-nests-too-deep = 公式在此处的嵌套超过 { $max } 层
formula-ends-early = 公式在应为数字、名称或 '(' 处结束
formula-never-closed = 此 '(' 没有闭合
formula-expected-close = 此处应为 ')' 或运算符
# $op 是输入的运算符（* / ^ ) 或 ,），乘号 · 或 × 给作 *。
formula-misplaced-operator = 此处应为数字、名称或 '('，却是 '{ $op }'
# $name 是输入的名称；$functions 列出各函数的名称。
formula-no-function = 没有函数 '{ $name }'：可用的函数有 { $functions }
# $name 是函数名："in sqrt( )"。
formula-expected-argument-end = { $name }( ) 中此处应为 ',' 或 ')'
# $arity 是函数接受的参数个数，$given 是实际给出的个数。
formula-arguments = { $name } 接受 { $arity } { $arity ->
       *[other] 个参数
    }，而不是 { $given } 个
# $from 是给出该名称的控制律所在的步骤。
formula-later-name = '{ $name }' 在第 { $step } 步中不可用：它来自第 { $from } 步的控制律
formula-is-function = '{ $name }' 是函数：请写成 { $name }( )
# $name 是 x1，即真实转速。
formula-true-speed = '{ $name }' 是真实转速，无速度传感器控制器无法得到它：请改用其估计值 x1h
# $name 是 x4 或 x5，即真实转子磁链。
formula-true-flux = '{ $name }' 是真实转子磁链，任何驱动都不测量它：请改用其估计值 x4h 或 x5h
# $name 是 xt1、xt4 或 xt5。
formula-unmeasured-error = '{ $name }' 是未测量状态的估计误差，无速度传感器控制器无从得知：论文把这类项归入 d̃2 和 d̃4，鲁棒项（robust·h²/(4ε)·z）正是针对它们设计的
formula-unknown-name = 未知名称 '{ $name }'（见名称列表）
formula-too-long = 公式有 { $length } 个字符，超过允许的 { $max } 个
formula-empty = 公式为空
formula-unopened = 此 ')' 之前没有 '('
formula-expected-operator = 此处应为运算符（乘积用 * 表示）
formula-too-many-operations = 公式需要 { $operations } 次运算，超过允许的 { $max } 次
formula-too-deep = 公式的值嵌套 { $depth } 层，超过允许的 { $max } 层：请减少括号的嵌套
# $error 是 formula-* 消息，带有其位置。
law-refused = law.v{ $step }：{ $error }
law-no-such-step = 没有第 { $step } 步：步骤为 1 至 4
law-none = 场景没有自定义控制律：请给出 law.v1、law.v2、law.v3 或 law.v4
law-no-own-law = 这一步没有自定义控制律
law-not-designed-one = 该控制律未给出其设计的动态
# 场景的 $laws 个自定义控制律中有 $failed 个。
law-not-designed-some = { $laws } 个控制律中有 { $failed } 个未给出其设计的动态
law-never-runs = 你的 { $before } 在全部 { $draws } 个抽取的状态上都不给出有限值，因此第 { $step } 步从未运行
law-no-share = 在论文的控制律几乎为零之处，你的 { $output }（{ $unit }）与给出设计动态的 { $output } 不同，偏差相对其大小不是有限值
# 在 $draws 个抽取的状态中有 $count 个；控制律不读取任何信号时 $reads 为 none，否则 $names
# 列出它读取的名称及其在该处的值（law-named-value）。
law-differs-infinitely = 在 { $draws } 个抽取的状态中有 { $count } 个，你的 { $output }（{ $unit }）与给出设计动态的 { $output } 相差无穷大{ $reads ->
        [none] ，且控制律不读取任何信号
       *[some] ，例如在 { $names } 处
    }
# 同 law-differs-infinitely；$value 是控制律给出的值：inf、-inf 或 NaN。
law-not-finite = 在 { $draws } 个抽取的状态中有 { $count } 个，你的 { $output }（{ $unit }）不是有限数：它给出 { $value }{ $reads ->
        [none] ，且控制律不读取任何信号
       *[some] （此时 { $names }）
    }
# 控制律读取的名称及其值："z1 = 0.25"。
law-named-value = { $name } = { $value }
law-paper-zero = 论文的控制律在整个运行中保持为零，而你的不是
