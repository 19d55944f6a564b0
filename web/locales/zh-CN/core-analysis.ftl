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
