# ページのラベル、ボタン、注記、メッセージ（表示される場所ごと）。
# 数値は変数として、すでにその言語の書き方で渡される。$reason、$warning、$description、$label という
# 名前の変数は、シミュレーションのコア自身の文言（当面は英語）を保持する。シナリオ（$scenario）、
# フィールドのキー（$key）、プリセットの名前（$preset）、コマンドはそのまま書き、翻訳しない。

## ヘッダ

page-title = IM Lab：速度センサレス誘導電動機制御
page-name = IM Lab
page-skip-link = プロットへ移動
page-intro = 速度センサレス誘導電動機制御：EKFオブザーバと四段階のバックステッピング制御器（Zhang, Wang, Bortoff et al., 2015）を、ブラウザ上で20 kHzでシミュレーションします。
help-links =
    .aria-label = 概要／ヘルプ
help-links-intro = 概要／ヘルプ：
help-student-guide = 学生向けガイド
help-lecturer-guide = 講師向けガイド
help-all-guides = すべてのガイド
language-menu = 言語

## レッスンの読み込み

lessons-not-loaded = レッスンの本文を読み込めませんでした：{ $reason }。「レッスン」タブをもう一度開くと再試行します。

## 複数の場所で共通のボタン

shared-cancel = 中止
shared-csv = CSV

## 実行バー：プリセット、「実行」、状態表示、リンク

run-preset = プリセット
run-button = 実行
run-settings = 設定
run-unrun = 設定が変更されましたが、まだ実行していません。「実行」またはEnterを押してください。アドレスと「リンクをコピー」は、画面上の実行を表します。
share-copy-link = リンクをコピー
export-png = PNG
share-copy-embed = 埋め込みコードをコピー
    .title = このシナリオについて、表示中の「時間応答」のプロットを示すiframeのコードをコピーします

## 結果：タブ、表示バー、指標

results =
    .aria-label = 結果
tabs =
    .aria-label = 表示
tab-plots = 時間応答
tab-walkthrough = 設計解説
tab-lessons = レッスン
tab-analysis = 解析
tab-challenge = 課題
present-button = 発表モード
    .title = プロジェクタ向けに文字とプロットを大きくします。設定は引き出しパネルに移ります
view-full-run = 実行全体
    .title = すべてのプロットに実行全体を表示します（プロットのダブルクリックやEscapeでも可）
view-fit = 起動過渡の後にy軸を合わせる
view-fit-from = 起動過渡の後にy軸を合わせる（t ≥ { $ms } ms）
view-fit-why = なぜこの時刻か
view-transient-reason = 起動過渡：{ $reason }。
figures-all = すべての指標
figures-fewer = 指標を減らす
figures-strip =
    .aria-label = この実行の指標
plots-hint = プロット上をドラッグすると、すべてのプロットを拡大します。ダブルクリック、Escape、または「実行全体」で実行全体に戻ります。凡例には、カーソル位置のサンプルで記録された値が表示されます。プロットをクリックすると、その時刻のすべての項を調べられます。

## ピン留めとその重ね描き（「時間応答」タブ）

pins-pin = この実行をピン留め
pins-overlay = 重ね描き
pins-column-omega = 速度 ω
pins-column-omega-hat = 推定速度 ω̂
pins-column-flux = 磁束 |φ|
pins-column-voltage = 電圧 u_sa
pins-unpin = ピンを外す
pins-item = ピン{ $n }：{ $legend }
pins-name = ピン{ $n }
pins-current = 現在
pins-difference = 現在 − ピン{ $n }
pins-overlay-title = { $column }：現在の実行とピン留めした実行
pins-difference-title = { $column }：現在 − ピン
pins-status-running = ピンを実行中（{ $count }個中{ $n }個目）：{ $percent } %
pins-status-done = ピン留めしました
pins-status-cancelled = ピン留めを中止しました
pins-link-too-long = アドレス内のピンは実行されませんでした：{ $length }文字あり、ピンの部分に許される{ $max }文字を超えています。
pins-link-malformed = アドレス内の不正な形式のピンを無視しました：{ $pins }。
pins-link-dropped = アドレス内のピンのうち、最初の{ $sent }個だけを実行しました。残りの{ $dropped }個は除外しました。
pins-rejected-first = { $scenario }をピン留めできませんでした：{ $reason }
pins-rejected-next = { $scenario }をピン留めできませんでした：{ $reason }
pins-rejected = { $list }。
pins-reason-unrun = 未実行：ピン留めが中止されました
pins-reason-cancelled = 中止されました

## メッセージ中の一覧

list-more = { $list } …ほか{ $count }件

## 実行の状態表示とメッセージ

run-status-starting = { $samples }サンプルを実行しています…
run-status-progress = 実行中：{ $total }サンプル中{ $done }サンプル
run-status-done = { $rows }サンプル、{ $ms } ms
run-status-ran-away = 暴走：{ $rows }サンプル、{ $ms } ms
run-status-stopped = { $rows }サンプルで停止しました
run-status-cancelled = { $percent } %で中止しました
run-status-worker-failed = 停止：シミュレーションのワーカーが失敗しました
run-stopped-early = 実行が途中で止まりました：{ $reason }。プロットは、それまでの{ $rows }サンプルを示しています。
run-ran-away = { $warning } プロットは電動機の挙動をそのまま示しています。
run-worker-not-started = シミュレーションのワーカーを起動できませんでした（{ $reason }）。ページを再読み込みして、もう一度お試しください。
run-worker-failed = シミュレーションのワーカーが失敗しました（{ $reason }）。ワーカーは再起動しました。「実行」を押して、もう一度お試しください。
run-worker-failed-pins = シミュレーションのワーカーが失敗しました（{ $reason }）。ワーカーは再起動しました。「実行」を押して、もう一度お試しください。ピン留めした実行は破棄されました：{ $pins }。
page-language-failed = ページの{ $language }のメッセージを読み込めませんでした（{ $reason }）。英語で表示しています。
page-messages-failed = ページの残りのテキストを読み込めませんでした（{ $reason }）。ツール、レッスン、設計解説にはこれが必要です。いずれかを使うと再度読み込みを試みます。
page-challenge-tools-failed = 「課題」タブの作成と採点の機能を読み込めませんでした：{ $reason }。タブをもう一度開くと再試行します。
page-lesson-map-failed = レッスンのマップを読み込めませんでした：{ $reason }。
page-no-lesson = 「{ $lesson }」という名前のレッスンはありません。レッスン：{ $lessons }。
lesson-differences-refused = コアがその一部を受け付けませんでした（{ $reason }）
lesson-differences-uncompared = レッスンの実行と比較できませんでした

## シミュレーションのワーカーが失敗した理由（上のメッセージの $reason）

worker-unknown-error = 不明なエラー
worker-unreadable = ワーカーからのメッセージを読み取れませんでした
worker-crash-panic = { $error }。Rustのパニック：{ $panic }
worker-crash-memory = { $error }。コアのメモリ不足と考えられます
pool-worker-failed = ワーカーが失敗しました（{ $reason }）
pool-worker-failed-restart = ワーカーが失敗しました（{ $reason }）。次の実行では新しいワーカーを起動します
worker-tools-not-loaded = ツールを読み込めませんでした（{ $reason }）。接続を確認して、もう一度お試しください。
compare-failed = 比較に失敗しました：{ $reason }
compare-running = 両方の予測器で実行しています…

## 書き出し

export-csv-starting = CSVを書き出しています…
export-csv-progress = CSVを書き出し中：{ $total }行中{ $rows }行
export-csv-done = CSVを書き出しました：{ $total }行
export-csv-cancelled = CSVの書き出しを中止しました
export-csv-cancelled-by-run = 新しい実行が始まったため、CSVの書き出しを中止しました。
export-csv-stopped = CSVの書き出しが止まりました
export-csv-failed-status = CSVの書き出しに失敗しました
export-csv-failed = CSVの書き出しに失敗しました：{ $reason }。
export-csv-gone = この実行はもうワーカーに保持されていません。もう一度実行してください
export-csv-refused = ブラウザが{ $megabytes } MBを超えるCSVの保持を拒否しました（{ $error }）。代わりにコマンドラインでこの実行を書き出してください：{ $command }
export-png-not-ready = プロットはまだ描画中です。少し待ってから書き出してください。

## 共有

share-link-copied = リンクをコピーしました。このリンクはこの実行をビット単位で正確に再現します。
share-copy-this-link = このリンクをコピーしてください：{ $link }
share-embed-title = IM Lab：{ $preset }、{ $plots }
share-embed-copied =
    埋め込みコードをコピーしました：この実行の{ $plots }の{ $count ->
       *[other] プロット
    }（表示中の「時間応答」のプロット）。スライドや講義ページに貼り付けてください。
share-embed-copy-this =
    この実行の{ $plots }の{ $count ->
       *[other] プロット
    }（表示中の「時間応答」のプロット）の埋め込みコードをコピーしてください：{ $code }
embed-unknown-plots = { $names }という名前のプロットはありません。代わりに{ $shown }を表示しています。プロット：{ $plots }。

## 設定より前のシナリオの結果（$scenario はそのシナリオ）


## 各ステップの自作の制御則（設定フォームと設計解説）

law-paper-default = 自作の制御則はまだありません：このステップは論文のv{ $step }で実行されます。

## 設定フォーム

settings-group-reference = 指令値
settings-group-controller = 制御器：バックステッピングまたは古典的なIFOC
settings-group-gains = バックステッピングのゲイン
settings-group-observer = オブザーバ（EKF）
settings-group-noise = ノイズとシード
settings-group-plant = プラント：シミュレーション上の電動機
settings-group-model = モデル：EKFと制御器が想定するもの
settings-group-load = 未知の負荷：ステップまたは点の表
settings-group-limits = 電圧制限（正方形）、定格、実行時間、タイミング
settings-group-drive = ドライブ：計算遅延、インバータの制限、PWM
settings-group-law = バックステッピングの各ステップの自作の制御則（空欄：論文の制御則）
settings-allowed-formula = 設計解説の「このステップを書く」に挙がっている名前による式。空欄：論文の制御則
settings-allowed-range = { $min } { $op } { $key } ≤ { $max }
settings-allowed-table = 点 t:value を{ $points }個まで（例：0:0,0.1:100）、時刻は0から増加。値は{ $min }から{ $max }まで
settings-allowed-whole = { $min } { $op } { $key } ≤ { $max }、整数
settings-allowed = 許容値：{ $values }
settings-link-rejected = アドレス内の一部の設定は却下され、プリセットの値のままです：{ $list }。
settings-link-refused = アドレス内のシナリオは却下されました：{ $reason }。代わりに{ $preset }を表示しています。
settings-preset-changed = プリセット{ $preset }：{ $description }。この実行は{ $fields }を変更しているため、プリセットの説明がその実行について述べていることは、この実行では成り立つとは限りません。
settings-idle = { $changed } 無視される設定：{ $idle }。
settings-idle-separator = {"。"}

## 指標欄と主な指標

figures-to-rated = { $value }（定格{ $rated } Aの{ $ratio }倍）
figures-nis-inside = { $value }（95 %区間 { $low }–{ $high }：内側）
figures-nis-outside = { $value }（95 %区間 { $low }–{ $high }：外側）
figures-exact = 厳密な値：{ $value }（{ $window }）
figures-no-value = 値なし：{ $reason }（{ $window }）
figures-trend-settled = 実行終了までに整定
figures-trend-ran-away = 実行が暴走：最終値ではない
figures-trend-drifting = EKFの負荷またはR_rのランダムウォーク推定値とともにドリフト中：より長い実行では別の値で終わる
figures-trend-fluctuating = ±{ $scatter }で変動中：最後のサンプルは最終値ではない
figures-trend-changing = まだ変化中：終了時に毎秒{ $rate }。実行を長くしてください
figures-trend-changing-to-go = まだ変化中：終了時に毎秒{ $rate }。実行を長くしてください（残り約{ $to-go }）
figures-trend-fit = 最後の{ $ms } msに当てはめた直線：毎秒{ $rate }、直線のまわりのサンプルのばらつき{ $scatter }。整定とは、直線の動きが{ $tolerance }以内で、ばらつきの四倍もその範囲に収まることをいう
figures-trend-fit-approach = 最後の{ $ms } msに当てはめた直線：毎秒{ $rate }、直線のまわりのサンプルのばらつき{ $scatter }。最後の三つの十分の一区間の平均は、{ $to-go }離れた値に近づいている。整定とは、直線の動きが{ $tolerance }以内で、ばらつきの四倍もその範囲に収まることをいう
figures-key-peak = |i_s|のピーク値 { $value }（定格の{ $ratio }倍）
figures-key-final =
    最終 ω − ω_d { $value }（{ $trend ->
        [settled] 整定
        [changing] まだ変化中
        [drifting] ドリフト中
        [fluctuating] 変動中
       *[ran-away] 暴走
    }）
figures-key-nis-inside = 平均NIS { $value }（95 %区間の内側）
figures-key-nis-outside = 平均NIS { $value }（95 %区間の外側）
figures-caption = この実行の指標：{ $figures }。

## プロット

plot-speed = 回転子速度
plot-speed-reference = ω_d 指令値
plot-speed-estimated = ω̂ 推定値
plot-speed-true = ω 真値
plot-speed-error = 速度追従誤差 ω − ω_d
plot-flux = 回転子磁束の大きさ
plot-flux-target = √ψ_d 目標値
plot-flux-estimated = |φ̂| 推定値
plot-flux-true = |φ| 真値
plot-current = 固定子電流
plot-current-a-estimated = î_sa 推定値
plot-current-b-estimated = î_sb 推定値
plot-current-a-true = i_sa 真値
plot-current-b-true = i_sb 真値
plot-voltage = 印加固定子電圧（制限後）
plot-voltage-limit-high = +制限
plot-voltage-limit-low = −制限
plot-z13 = 追従誤差
plot-z13-flux = z3 = |φ̂|² − ψ_d（Wb²、右軸）
plot-z24 = 仮想入力の誤差
plot-z24-torque = z2 トルク誤差（rad/s²）
plot-z24-flux = z4 磁束変化率の誤差（Wb²/s、右軸）
plot-est = 推定誤差
plot-est-flux = |φ| − |φ̂|（Wb、右軸）
plot-not-driving = { $title }（比較のために計算。電動機は駆動していない）
plot-caption = { $title }。縦軸は{ $unit }、横軸は時間 t（s）。信号：{ $signals }。
plot-caption-two-axes = { $title }。縦軸は{ $unit }（左）と{ $unit2 }（右）、横軸は時間 t（s）。信号：{ $signals }。
plot-caption-keys = プロットにフォーカスし、矢印キーで実行をサンプルごとに調べられます（Shift：ウィンドウの1 %ずつ）。

## 「解析」タブ


## 「レッスン」タブ


## 「課題」タブ


## The challenge panel's controls, built with the page

challenge-progress =
    .aria-label = 完了した課題の実行
challenge-cancel = 確認を中止
challenge-copy = 提出リンクをコピー
challenge-open-failed = 課題を開けませんでした：{ $reason }。代わりに既定のシナリオを表示しています。
law-checking = 制御則を設計した動特性と照合しています…
law-verdict-failed = 制御則の判定を計算できませんでした：{ $reason }
walkthrough-load-failed = 設計解説を読み込めませんでした。接続を確認して、ページを再読み込みしてください。
lesson-panel =
    .aria-label = レッスン
challenge-panel =
    .aria-label = 課題
stale-back = 元のシナリオへ
