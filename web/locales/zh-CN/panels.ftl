map-heading = 模型误差图
# 误差图的介绍在三段代码处断开：plant.*、model.* 和一个示例轴 plant.rr=-10%..+10%:11。
# map-intro-start 位于“plant.*”之前，map-intro-model 位于“plant.*”与“model.*”之间，
# map-intro-axes 位于“model.*”与示例之间，map-intro-example 位于示例之后。
map-intro-start = 当电机与 EKF 和控制器所假设的不一致时，结果在多大程度上仍成立？在一个或两个电机参数（
map-intro-model = ）或模型参数（
map-intro-axes = ）上运行当前场景，每个取值都用所有种子运行，并显示每个指标在各种子上的中位数和范围。轴写作 KEY=LO..HI:N，可以用数值，也可以用相对于另一方的相对误差：{ " " }
map-intro-example = { " " }表示电机的转子电阻从比模型值低 10% 到高 10%。其他任何数值字段，例如增益（k1=-20%..+20%:5）、EKF 的调参或磁链目标值，都相对于场景自身的值来读取。
map-axis = 轴
map-second-axis = 第二轴（可选）
map-seeds = 种子数
map-run-button = 运行误差图
sweep-heading = 闭环频率响应
sweep-intro = 在当前场景上扫描正弦转速参考值 ω_d = 偏移 + A·sin(2πft)，在每次运行的前半段之后拟合 ω（以及控制器的转速估计值）的基波，并读出 −3 dB 带宽和 200 Hz 处的相位。A 应足够小，使电压不触及限幅；表中会报告饱和情况。经典 IFOC 需要一个工作转速（其 MRAS 在零速附近失效）和更长的运行时间（其转速环为 10 Hz）。
# 扫描的字段：从 … Hz，至 … Hz，点数，偏移 … rad/s，运行时长 … s，工作线程。
sweep-from = 从
sweep-to = 至
sweep-points = 点数
sweep-offset = 偏移
sweep-run-length = 运行时长
sweep-workers = 工作线程
sweep-variants = 方案
sweep-variant-euler = 欧拉 EKF（论文）
sweep-variant-rk4 = RK4 EKF
sweep-variant-perfect = 理想观测器
sweep-variant-delay = 欧拉 EKF，一个采样周期延时
sweep-variant-ifoc = 经典 IFOC，转矩前馈
sweep-variant-ifocpi = 经典 IFOC，仅 PI
sweep-run-button = 运行扫描
seeds-heading = 多种子扫描
seeds-intro = 用 N 个噪声种子并行运行当前场景，并逐个采样点显示转速误差和估计误差的均值及最小–最大区间带。
# 种子个数的标签。
seeds-count = 种子数
seeds-run-button = 运行多种子
motor-heading = 自定义电机：由铭牌和试验数据得到
lessons-heading = 课程
lessons-intro = 每课载入一个预设并运行，同时在图旁打开课程面板，给出观察要点、问题、提示和答案。图上方的指标可以回答大多数问题。
challenges-heading = 设计挑战
challenges-intro = 挑战是放在链接中的设计任务：学生只能修改部分设置，当每项判据在标称运行及其变体上都成立时即为通过。下面的链接打开内置挑战；在“挑战”选项卡中可以编写新的挑战。
compose-heading = 编写挑战
grade-heading = 全班评分
# 评分的介绍在命令“imlab grade”处断开：grade-intro-start 位于其前，grade-intro-end 位于其后。
grade-intro-start = 在此浏览器中按一个挑战为班级文件中的每个提交链接评分：数据不会离开浏览器。班级文件每行一个链接，也可以是课程平台导出的 CSV，其中有一列链接（其他列，如学生姓名，会带入结果中）。所得 CSV 与{ " " }
grade-intro-end = { " " }对同样的文件写出的 CSV 逐字节相同。已取消或中断的评分会保存在此浏览器中，直到下一次评分，按“评分”即可从中断处继续。
grade-challenge-input =
    .placeholder = 内置挑战的名称或挑战链接
grade-class-file = 班级文件
# 误差图所显示指标的菜单标签。
map-figure = 指标
map-progress =
    .aria-label = 已完成的误差图运行
sweep-csv = CSV（第一个方案）
seeds-progress =
    .aria-label = 已完成的多种子运行
compose-fill = 按当前场景填写
grade-challenge = 挑战
grade-paste = 或粘贴链接，每行一个
grade-run = 评分
grade-csv = 下载 CSV
grade-progress =
    .aria-label = 已评分的提交
grade-table =
    .aria-label = 全班成绩
stale-map = 这张误差图属于较早的场景（{ $scenario }），而不是当前的设置。按“运行误差图”即可更新。其 CSV 注明了它所对应的场景。
stale-sweep = 这些伯德图和这张表属于较早的场景（{ $scenario }），而不是当前的设置。按“运行扫描”即可更新。其 CSV 不注明所属场景，在此之前不可导出。
stale-seeds = 这些多种子区间带属于较早的场景（{ $scenario }），而不是当前的设置。按“运行多种子”即可更新。其 CSV 不注明所属场景，在此之前不可导出。
stale-challenge = 此判定属于较早的场景（{ $scenario }），而不是当前的设置。按“运行并检查”即可更新。“复制提交链接”复制的是它所检查的那组设置的链接。
# 设计详解中 EKF 预测器的比较。
stale-compare = 此比较属于较早的场景（{ $scenario }），而不是当前的设置。先按“运行”，再按比较按钮，即可更新。
