# レッスンの一覧と、プロットの横に表示されるレッスンパネル。

## 「レッスン」タブの一覧

lesson-numbered-title = { $number }. { $title }
lesson-list-question = 問い：{ $question }
lesson-start = レッスン{ $number }を開始

## レッスンパネル

lesson-count = レッスン{ $number }（全{ $count }）
lesson-run = {" "}· 実行：{ $run }
lesson-look-head = 観察のポイント
lesson-question-head = 問い
lesson-hint = ヒント
lesson-show-answer = 解答を表示（講師用）
lesson-previous = ← 前へ
lesson-next = 次へ →
lesson-close = レッスンを閉じる
lesson-copy-link-short = リンクをコピー
lesson-copy-link-rest = （このレッスン）
lesson-link-copied = リンクをコピーしました。このリンクを開くと、このレッスンとその実行が表示されます。
lesson-copy-this-link = このリンクをコピーしてください：{ $link }
lesson-load-run = レッスンの実行を読み込む
lesson-own-settings = このリンクには独自の設定が含まれており、レッスンの実行ではなく、リンクの設定のとおりに表示しています：{ $differences }。レッスンがその実行について述べていることは、この設定では成り立つとは限りません。
