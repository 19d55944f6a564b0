# 解析ツールと課題ツールの文言：「解析」タブ（スイープ、シード帯、モデル誤差マップ）、学生に表示される
# 課題パネル、講師が用いる「課題」タブ（作成、その確認、クラスの採点）。

## 周波数応答スイープ：ボード線図と表（web/analysis/analysis.js）

sweep-plot-magnitude = ω/ω_dのゲイン
sweep-plot-phase = ω_dに対するωの位相
sweep-axis-degrees = 度
sweep-series-unsettled = { $variant }（未整定）
sweep-unsettled =
    { $count ->
       *[other] { $count }点が整定していませんでした（白抜きのマーカー）。帯域幅と200 Hzでの位相は、これらの点からは読み取りません。実行を長くすれば整定する場合があります。
    }
sweep-unsettled-point = { $variant }、{ $frequency }：{ $reason }
sweep-hz = { $value } Hz
sweep-degrees = { $value } °
sweep-head-variant = 構成
sweep-head-bandwidth = −3 dB帯域幅
sweep-head-phase = 200 Hzでの位相
sweep-head-saturation = 最大飽和率
sweep-head-failed = 失敗した点
sweep-head-unsettled = 未整定の点
sweep-head-peak = |i_s|のピーク値 (A)
sweep-bandwidth-unsettled = 表示しない：未整定の点にもとづくことになるため
sweep-bandwidth-below = 最低周波数より下
sweep-not-reached = 周波数格子内で未到達
sweep-phase-not-reached-settled = 整定した点では未到達
sweep-unsettled-cell = { $count }点：{ $frequencies }
sweep-peak-none = 測定なし
sweep-peak = { $peak }（定格 { $rated }）
sweep-peak-over = { $peak }（定格 { $rated }）。定格を超える点は{ $count }点：{ $frequencies }

## シード帯：プロット（web/analysis/analysis.js）

seeds-plot-error = シードにわたる速度誤差 ω − ω_d（平均、最小、最大）
seeds-plot-estimate = シードにわたる推定誤差 ω − ω̂（平均、最小、最大）
seeds-series-mean = 平均
seeds-series-min = 最小
seeds-series-max = 最大

## 周波数応答スイープ：フォームの実行、状態表示、リンク（web/analysis/sweeps.js）

sweep-workers-invalid = workers = { $value }：1～8の整数を指定してください。
sweep-status-checking = スイープを確認しています…
sweep-refused = { $reason }。
sweep-not-run = スイープは実行されませんでした。設定が無効か、ここでは許可されていません。理由は上部のメッセージに表示されています。
sweep-status-running = スイープを実行しています…
sweep-status-done =
    { $workers ->
       *[other] { $variants } × { $points } 回の実行を、{ $workers }個のワーカーで{ $ms } msで完了しました。
    }
sweep-status-cancelled = スイープを中止しました。
sweep-status-failed = スイープに失敗しました：{ $reason }
sweep-link-refused = アドレス内のスイープ（{ $link }）は実行されませんでした：{ $reason }。

## シードごとの実行：フォームの実行と状態表示（web/analysis/seeds.js）

seeds-count-invalid = seeds = { $value }：1～1000の整数を指定してください。
seeds-not-run = シードの実行は行われませんでした。設定が無効か、ここでは許可されていません。理由は上部のメッセージに表示されています。
seeds-status-starting = 複数シードで実行しています…
seeds-status-running = 複数シードで実行しています：{ $percent } %
seeds-status-done = { $seeds }個のシードのうち{ $runs }個（{ $first }～{ $last }）の実行が完了しました。
seeds-status-cancelled = シードの実行を中止しました。
seeds-status-failed = シードの実行に失敗しました：{ $reason }

## モデル誤差マップ：実行と状態表示（web/analysis/robust.js）

map-status-starting = { $cells }セル × { $seeds }シードを実行しています…
map-status-running = マップを実行しています：{ $total }回中{ $done }回
map-refused = マップは実行されませんでした：{ $reason }。
map-not-run = マップは実行されませんでした。設定が無効か、ここでは許可されていません。理由は上部のメッセージに表示されています。
map-failed = マップの実行に失敗しました：{ $reason }
map-status-cancelled = マップを中止しました。{ $cells }セル中{ $finished }セルが完了して表示されています。残りのセルは実行されていません。
map-status-done = { $cells }セル × { $seeds }シード（{ $first }–{ $last }）を{ $seconds } sで実行しました。
map-link-refused = アドレス内のマップ（{ $link }）は実行されませんでした：{ $reason }。

## モデル誤差マップ：一つの軸に沿ったプロット（web/analysis/map-plot.js）

map-plot-title = シードにわたる{ $figure }：中央値と最小–最大の帯
map-series-min = 最小
map-series-median = 中央値
map-series-max = 最大
map-gap = { $value }（{ $runs }シード中{ $ranAway }シード）
map-gap-percent = { $value } %（{ $runs }シード中{ $ranAway }シード）
map-gaps = 一部のシードが暴走したため描画していない値：{ $cells }。

## モデル誤差マップ：表と凡例（web/analysis/map-table.js、map-colours.js）

map-figure-unit = { $figure }（{ $unit }）
map-cell-not-run = 未実行
map-cell-title = { $scenario }：{ $runs }シード中、暴走{ $ranAway }、非整合{ $inconsistent }、定格電流超過{ $overRating }、終了時に速度誤差が未整定{ $unsettled }。{ $figure } { $min }～{ $max }
map-grid-corner = { $rows } ↓ / { $columns } →
map-head-median = 中央値
map-head-range = 最小 – 最大
map-range = { $min } – { $max }
map-key = { $figure }、暴走しなかったシードにわたる中央値（{ $seeds }シード）。色：{ $colours }。✕ k/N：N個のシードのうちk個で実行が暴走した（実行自身のページがそう示したか、数値的に破綻した）ことを示し、値としては色付けしません。⚠ EKFが非整合でした。I↑ k/H：持ちこたえたH個のシードのうち、k個が起動後に電動機の定格電流を超える電流を流しました。~ k/H：k個が速度誤差の整定しないまま終わりました（これら二つは枠で囲み、中央値で色付けします）。セルをクリックするとその実行を開きます（シード{ $seed }）。
map-scale-diverging = 青 −{ $max } から白 0 を経て赤 { $max }
map-scale-log = 対数目盛、淡色 { $min } から濃色 { $max }
map-scale-linear = 線形目盛、淡色 { $min } から濃色 { $max }
map-scale-none = なし

## 課題パネル：課題リンクを開いた学生に表示される内容（web/challenge/challenge.js）

challenge-heading = 課題
challenge-link-rejected = この課題リンクは却下されました：{ $reason }。代わりに既定のシナリオを表示しています。
challenge-submission-another = この提出リンクは別の課題のものです（課題の部分が編集されています）。採点していません。
challenge-submission-refused = この提出リンクは受け付けられませんでした：{ $reason }。採点していません。課題は基本設定から始まります。
challenge-submission-rejected = この提出リンクは却下されました：{ $reason }。採点していません。課題は基本設定から始まります。
challenge-run = 実行して確認
challenge-settings = あなたの設定
challenge-settings-hint = 変更できるのは{ $fields }だけです。その他の設定は課題によって固定されています。
challenge-checklist = チェックリスト
challenge-task = 課題の全文
challenge-verdict-pending = 未確認：最初の実行を計算しています。
challenge-need-pending = { $label }（{ $figure }）：未確認
challenge-verdict-link-refused = ✗ 採点していません：リンクの設定が受け付けられませんでした（上記を参照）。変更できる設定を変えて実行してください。
challenge-verdict-cancelled = ✗ 確認を中止しました：採点していません。もう一度実行すると確認します。
challenge-verdict-failed = ✗ 確認に失敗しました：{ $reason }。採点していません。
challenge-verdict-edited = これは組み込みの課題{ $name }ではありません。条件が編集されています。
challenge-verdict-rerun = 画面上の実行は採点対象の実行ではありません（固定された設定が異なります）。課題の設定と、あなたが変更できる設定とで、公称の実行をもう一度行いました。
challenge-checking =
    確認しています：{ $runs ->
       *[other] { $runs }回
    }の実行のうち{ $done }回が完了（公称の実行と{ $variants ->
       *[other] { $variants }個のバリアント
    }）…
challenge-refusal-not-run = あなたの設定は有効な解答ではありません：{ $reason }。実行していません。
challenge-verdict-not-run = ✗ 実行していません。あなたの設定は有効な解答ではありません：{ $reason }。
challenge-refusal-not-graded = あなたの設定は有効な解答ではありません：{ $reason }。採点していません。
challenge-verdict-not-graded = ✗ 採点していません。あなたの設定は有効な解答ではありません：{ $reason }。
challenge-copied = 提出リンクをコピーしました。このリンクはこれらの実行をビット単位で正確に再現します。
challenge-copy-by-hand = この提出リンクをコピーしてください：{ $url }

## 課題パネル：チェックリストとその操作（web/challenge/checklist.js）

checklist-not-measured = 未測定
checklist-never = 到達せず（∞）
checklist-value-unit = { $value } { $unit }
checklist-passed =
    { $criteria ->
       *[other] ✓ 合格：すべての基準（{ $criteria }個）を満たしています。
    }
checklist-passed-variants =
    { $criteria ->
       *[other] ✓ 合格：すべての基準（{ $criteria }個）を満たしています（公称の実行と{ $variants ->
           *[other] { $variants }個のバリアント
        }）。
    }
checklist-failed = ✗ 不合格：{ $criteria }個の基準のうち{ $met }個を満たしています。
checklist-failed-variants =
    ✗ 不合格：{ $criteria }個の基準のうち{ $met }個を満たしています（公称の実行と{ $variants ->
       *[other] { $variants }個のバリアント
    }）。
checklist-pass = ✓ 合格
checklist-fail = ✗ 不合格
checklist-criterion = { $label }：{ $value }（要件 { $bound }）
checklist-criterion-worst = { $label }：{ $value }（要件 { $bound }、最悪の実行：{ $run }）
checklist-reason = — { $reason }

## 課題パネル：変更できる設定のつまみ（web/challenge/knobs.js）

challenge-knob-doc = { $doc }（{ $unit }）
challenge-allowed-choice = 許容値：{ $options }のいずれか
challenge-allowed-formula = 許容値：自作の式（{ $unit }。使える名前は設計解説の「このステップを書く」に一覧があります）
challenge-allowed-range = 許容範囲：{ $lo }～{ $hi }
challenge-allowed-range-unit = 許容範囲：{ $lo }～{ $hi } { $unit }

## 課題パネル：見出しと課題の出所（web/challenge/origin.js）

challenge-kind = 課題
challenge-origin-builtin = 組み込みの課題
challenge-origin-mine = このブラウザであなたが出題：このブラウザがまさにこの課題を作成しました（基準値とタイトルは変更されていません）
challenge-origin-other = このブラウザで出題した課題ではありません
challenge-origin-unknown = このブラウザには、作成した課題の記録がありません
challenge-fingerprint = フィンガープリント
challenge-edited = 編集されています：このリンクは組み込みの課題{ $name }のタイトルをもっていますが、その条件はもっていません。{ $name }としてではなく、リンクの内容どおりの課題として採点されます。

## 「レッスン」タブの組み込みの課題（web/challenge/builtins.js）

builtins-open = 課題{ $name }を開く
builtins-failed = 組み込みの課題を一覧表示できませんでした。

## 「課題」タブ：課題の作成（web/challenge/challenge-compose.js）

compose-intro = 課題は設定中のシナリオ（基本シナリオ）から始まります。学生はここに挙げたフィールドだけを、その範囲内で変更でき、すべての基準を満たせば合格です。まずシナリオを設定して実行してください。基準は、その指標から、この実行より20 %厳しい値であらかじめ入力されます。
compose-base = 基本：
compose-title = タイトル
compose-title-default = 課題：{ $preset }
compose-make = 課題リンクを作成
compose-no-run = 指標を取得できる、このシナリオの完了した実行がありません。実行してから、もう一度「現在のシナリオから入力」を押してください。
compose-invalid = 課題が無効です：{ $reason }
compose-link = 課題リンク
compose-kept = このブラウザは、この課題を作成したことを記録しています。このリンクをここで開くと「このブラウザであなたが出題」と表示されます。基準値やタイトルを変えたコピーでは表示されません。
compose-not-kept = このブラウザは、作成した課題を記録できません（ストレージまたはWeb Cryptoがここでは使えません）。このリンクをここで開いても、あなたが出題したことは表示できません。
compose-copy-link = 課題リンクをコピー
compose-link-copied = 課題リンクをコピーしました。
compose-link-not-copied = 上の課題リンクを選択してコピーしてください。
compose-open = 学生として開く
compose-brief = 課題の説明文（スライドや講義ページ用）
compose-copy-brief = 説明文をコピー
compose-brief-copied = 説明文をコピーしました。
compose-brief-not-copied = 上の説明文を選択してコピーしてください。

## 「課題」タブ：作成画面の行（web/challenge/compose-rows.js）

compose-allow-legend = 学生が変更できるフィールド
compose-field = フィールド
compose-field-option = { $field } — { $doc }
compose-add = 追加
compose-remove = 削除
    .aria-label = { $field }を削除
compose-allow-formula = 学生の自作の式（{ $unit }）
compose-allow-choices = { $field }：選択肢（a|b）
compose-allow-from = 下限
compose-allow-to = 上限
compose-allow-now-unit = { $unit }（現在 { $value }）
compose-allow-now = （現在 { $value }）
compose-need-legend = 基準：この実行の指標
compose-need-hint = 「すべての実行」にチェックを入れると、基準はすべてのバリアントでも満たす必要があります（最悪の実行で判定）。
compose-need = { $label }（{ $figure }）
compose-need-now = { $label }（{ $figure }）— 現在 { $value }
compose-need-now-unit = { $label }（{ $figure }）— 現在 { $value } { $unit }
compose-need-op = { $figure }：制約の種類
compose-need-bound = { $figure }：基準値
compose-need-bound-unit = { $figure }：基準値 { $unit }
compose-op-max = 上限
compose-op-min = 下限
compose-op-abs = |値|の上限
compose-op-band = 95 %区間の内側
compose-bound-none = なし
compose-need-all-runs = すべての実行
compose-vary-legend = ロバスト性のバリアント（任意）
compose-vary = バリアント：seeds:A..B、または学生の設定に上乗せする設定を | で区切って指定
    .placeholder = seeds:2..10  または  model.j=0.016|model.j=0.024
compose-vary-seeds = シード2～10

## 「課題」タブ：合格できる設計があるかの確認（web/challenge/compose-check.js）

compose-check-progress =
    .aria-label = 課題の確認：完了した実行
compose-check-cancel = 確認を中止
compose-check-starting = 許容範囲内で合格する設計があるかを確認しています…
compose-check-running =
    許容範囲内で合格する設計があるかを確認しています：{ $runs ->
       *[other] { $runs }回
    }の実行のうち{ $done }回（{ $designs ->
       *[other] { $designs }個の設計
    }）…
compose-check-cancelled = 確認を中止しました。許容範囲内で合格する設計があるかどうかはわかりません。確認するには、もう一度リンクを作成してください。
compose-check-failed = 確認に失敗しました：{ $reason }。
compose-check-base-design = 基本シナリオ（フィールドの変更なし）
compose-check-failure = { $figure }：{ $value }（基準 { $bound }）
compose-check-failure-changing = { $figure }：{ $value }（基準 { $bound }、まだ変化中）
compose-check-unmeasured = { $figure }：{ $reason }
compose-check-base-passes = 基本シナリオのままで合格します。何も変更しない学生も合格します。
compose-check-base-fails = 基本シナリオ（フィールドの変更なし）は不合格です：{ $failures }。
compose-check-tried =
    確認では、{ $designs ->
       *[other] { $designs }個の設計
    }を{ $runs ->
       *[other] { $runs }回の実行
    }で試しました（上限 { $budget }回）。まず基本シナリオを、次に変更するフィールドの少ない設計から順に、範囲の両端から内側へ向かって試します（収まる場合はすべての組み合わせ）。
compose-check-solvable = ✓ 許容範囲内で合格する設計があります：{ $design }（試した{ $tried }個の設計のうち{ $passing }個が合格）。
compose-check-unsolved = ✗ 試した{ $tried }個の設計のうち、合格するものはありません。基準値が達成できない値なのかもしれません。最も近かったのは { $design } です（{ $failures }）。

## 「課題」タブ：クラスの採点（web/challenge/grade.js）

grade-refused = 採点していません：{ $reason }。
grade-no-challenge = 課題を指定してください：組み込みの課題の名前か課題リンク
grade-no-file = クラスのファイルを選ぶか、リンクを一行に一つずつ貼り付けてください
grade-no-submission = ファイルに提出が含まれていません
grade-read-as = クラスのファイルを{ $encoding }として読み込みました（UTF-8ではありません）。
grade-status-reading = クラスのファイルを読み込んでいます…
grade-status-grading = { $total }件の提出を採点しています…
grade-status-grading-kept = { $total }件の提出を採点しています（うち{ $kept }件は前回の採点結果を使用）…
grade-count = { $total }件中{ $done }件を採点済み
grade-status-done = { $total }件中{ $total }件を採点しました：合格は{ $passed }件です。
grade-not-stored = ブラウザのストレージにこの採点結果を保存できませんでした。今すぐダウンロードしてください。
grade-status-cancelled-kept = 中止しました：{ $total }件中{ $graded }件を採点済みで、このブラウザに保存されています。「採点」を押すと、そこから続けます。
grade-status-cancelled-lost = 中止しました：{ $total }件中{ $graded }件を採点済みですが、保存されていません（ブラウザのストレージが拒否しました）。
grade-status-stopped-kept = 採点が止まりました：{ $reason }。{ $total }件中{ $graded }件を採点済みで、このブラウザに保存されています。「採点」を押すと、そこから続けます。
grade-status-stopped-lost = 採点が止まりました：{ $reason }。{ $total }件中{ $graded }件を採点済みですが、保存されていません（ブラウザのストレージが拒否しました）。
grade-status-cancelled-reading = クラスのファイルの読み込み中に中止しました。何も採点していません。
grade-downloaded-partial = { $total }行のうち最初の{ $rows }行を順にダウンロードしました。「採点」を押すと止まったところから続けます。また、{ $command } でファイルを完成させることもできます。

## 「課題」タブ：クラスの表（web/challenge/grade-table.js）

grade-pending = 未採点
grade-pass = ✓ 合格
grade-fail = ✗ 不合格
grade-head-line = 行
grade-head-verdict = 判定
grade-head-link = リンク
grade-value-reason = { $value }：{ $reason }
grade-worst-run = { $text }（最悪の実行：{ $run }）

motor-intro = 固定子の直流抵抗、定格電圧での無負荷試験、拘束試験（IEEE Std 112）から、imlab motor と同じように電動機の等価回路を推定し、どの値が推定値かを示します。その後、この電動機から導出した設計で、電動機をプラントとモデルの両方として実行します。各試験は一つの測定値で、線間電圧、線電流、入力電力、周波数をカンマで区切って書きます。
motor-rs = 一相あたりの固定子抵抗（直流試験）
motor-no-load = 無負荷試験
motor-locked = 拘束試験
motor-nema = NEMA デザインの記号
motor-rated = 銘板：電圧、周波数、電流
motor-j = 回転子の慣性モーメント
motor-np = 極対数
motor-run-button = 等価回路を推定
motor-example-button = 例を入力
motor-example-filled = フォームには、2.2 kW、400 V の機械が、試験室で書き留めるとおりに入っています：銘板と、その等価回路が与える測定値です（カタログの電動機ではなく、シミュレーション上の試験室です）。
motor-open = 導出した設計でこの電動機を実行
