# 教学工具在各课和设计详解载入之前显示的文字：查看面板、步骤控制律编辑器（在设计详解和设置中）
# 以及设计详解自身的说明。核心给出的文字（单位、各项的含义、判定和错误信息）以变量传入，暂为英文。

## 查看面板（inspect-panel.js）：某一采样点上设计的每一项

inspect-title = 查看采样点 k = { $k }，t = { $time } s
inspect-copy = 复制精确值
inspect-copied = 已复制
inspect-copy-failed = 复制失败：请直接选中表格
inspect-close = 关闭（Esc）
inspect-exact = 精确值：{ $value }
inspect-group-step = 第 { $step } 步
inspect-group-voltage = 电压 (54) 与限幅
inspect-group-estimate = 估计值 x̂ (k|k)
inspect-group-measured = 测量值与真实值
inspect-term = 项
inspect-value = 值
inspect-unit = 单位
inspect-meaning = 含义
inspect-gain-caption = 卡尔曼增益 K_k（A⁻¹ × 状态单位）与 L = K_k/Ts（每秒）
inspect-gain-row = 行

## 步骤的自定义控制律（law-editor.js）

law-write = 写出这一步
law-names = 可用的名称和函数
law-names-name = 名称
law-names-symbol = 符号
law-names-unit = 单位
law-names-meaning = 含义
law-names-functions = 可使用 + − * / ^（或 · 和 −）、括号、数字以及函数 { $functions }。
law-error-at = 第 { $at } 个字符处：{ $reason }
law-stale = 并非当前输入的控制律：所显示的运行、此判定及残差图针对的是 { $output } = { $law }。{ $verdict }
law-stale-after = 并非当前输入的控制律：所显示的运行、此判定及残差图针对的是 { $previous } = { $previousLaw } 之后的 { $output } = { $law }。{ $verdict }

## 设计详解（walkthrough.js）

