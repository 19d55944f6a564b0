# 课程列表，以及图旁的课程面板。

## “课程”选项卡中的列表

lesson-numbered-title = { $number }. { $title }
lesson-list-question = 问题：{ $question }
lesson-start = 开始第 { $number } 课

## 课程面板

lesson-count = 第 { $number } 课，共 { $count } 课
lesson-run = {" "}· 运行 { $run }
lesson-look-head = 观察要点
lesson-question-head = 问题
lesson-hint = 提示
lesson-show-answer = 显示答案（供教师使用）
lesson-previous = ← 上一课
lesson-next = 下一课 →
lesson-close = 关闭本课
# 演示模式只显示按钮标签的前一部分（“复制链接”）。
lesson-copy-link-short = 复制链接
lesson-copy-link-rest = （本课）
lesson-link-copied = 链接已复制：它会打开本课及其运行。
lesson-copy-this-link = 请复制此链接：{ $link }
lesson-load-run = 载入本课的运行
lesson-own-settings = 此链接带有自己的设置，页面按链接中的设置显示，而不是本课的运行：{ $differences }。本课关于其运行的说法不一定适用于这些设置。
