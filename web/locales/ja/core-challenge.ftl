# 設計課題とその採点についてのコアのメッセージ：課題リンクや提出リンクが却下された理由、課題の文面、
# 各基準の判定、クラスの採点。キー、フィールド、指標、設定（c=1、allow.FIELD、need.FIGURE=OP、
# seeds:A..B、try.FIELD、mean_nis、load.torque = 0）はリンク自身の文言なので、そのまま残す。
# 引用された入力は引用符を残す。

## 却下された課題リンクまたは提出リンク

challenge-not-percent-encoded = フィールド '{ $key }' = '{ $value }'：有効なパーセントエンコードのUTF-8ではありません
challenge-too-long = 課題の長さは{ $bytes }バイトで、許容される{ $max }バイト（{ $kib } KiB）を超えています
challenge-unknown = '{ $name }' は課題リンクでも組み込みの課題（{ $names }）でもありません
challenge-unsupported-version = フィールド 'c' = '{ $value }'：対応していない課題のバージョンです。許容値：{ $version }
challenge-unknown-key = '{ $key }' は課題のフィールドではありません（{ $fields }）
challenge-missing = フィールド '{ $key }' がありません
challenge-builtin-extra = フィールド '{ $key }' は challenge={ $name } の後には置けません：組み込みの課題のリンクには challenge=NAME と学生の try.FIELD の部分しか入りません
challenge-stray =
    リンクの c={ $version } の前に余分な{ $count ->
       *[other] 文字
    } '{ $stray }' があります：{ $count ->
       *[other] 削除してください
    }
challenge-version-missing = フィールド 'c' がありません（課題は c={ $version } で始まります）
challenge-title-too-long = フィールド 'title' は{ $chars }文字あり、許容される{ $max }文字を超えています
challenge-bad-base = フィールド 'base'：{ $error }
challenge-no-criteria = 基準がありません：need.FIGURE=OP を一つ以上加えてください
challenge-too-many-criteria = 基準が{ $count }個あり、許容される{ $max }個を超えています
challenge-vary-unused = フィールド 'vary'：バリアントを使う基準がありません（robust= に基準の指標を挙げてください）
challenge-robust-without-vary = フィールド 'robust'：バリアントがありません（vary= を加えてください）
challenge-allow-unknown-field = フィールド '{ $key }'：'{ $field }' はシナリオのフィールドではありません
challenge-allow-formula = フィールド '{ $key }' = '{ $value }'：ステップの制御則は allow.{ $field }=formula で許可します
challenge-allow-range = フィールド '{ $key }' = '{ $value }'：LO..HI（LO ≤ HI である二つの数）を指定してください
challenge-allow-refused = フィールド '{ $key }' = '{ $value }'：{ $error }
challenge-allow-choice = フィールド '{ $key }' = '{ $value }'：{ $options } から互いに異なる名前を選び、| で区切って指定してください
challenge-need-unknown-figure = フィールド '{ $key }'：'{ $figure }' は指標ではありません（{ $figures }）
challenge-need-band = フィールド '{ $key }' = 'band'：区間をもつのは mean_nis だけです
challenge-need-op = フィールド '{ $key }' = '{ $value }'：max:B、min:B、abs:B、band のいずれかを指定してください
challenge-need-no-load-step = フィールド '{ $key }'：基本シナリオに負荷ステップがありません（load.torque = 0、または代わりに負荷の表を使用）
challenge-vary-seeds = フィールド 'vary' = '{ $value }'：seeds:A..B（A ≤ B ≤ { $max_seed } の整数で、シードは{ $max }個まで）を指定してください
challenge-vary-too-many = フィールド 'vary'：バリアントが{ $count }個あり、許容される{ $max }個を超えています
challenge-vary-variant-refused = フィールド 'vary'、バリアント{ $number }：{ $error }
challenge-vary-variant-empty = フィールド 'vary'、バリアント{ $number }が空です
challenge-variant-refused = バリアント '{ $overrides }'：{ $error }
challenge-robust-unknown = フィールド 'robust' = '{ $value }'：'{ $figure }' はどの基準の指標でもありません（または二回指定されています）
challenge-is-submission = フィールド 'try.{ $key }'：これは課題ではなく提出です（その課題に照らして採点してください）
challenge-another = この提出は別の課題のものです（課題の文面が異なります）
challenge-try-not-allowed = フィールド '{ $field }' は変更できません
challenge-try-not-number = フィールド 'try.{ $field }' = '{ $value }'：数ではありません
challenge-try-outside = { $setting } は範囲 { $range } の外です
challenge-try-not-option = { $setting } は { $options } のいずれでもありません
challenge-compose-range-and-options = フィールド '{ $key }'：LO と HI（範囲）か選択肢のどちらか一方だけを指定してください
challenge-judge-runs = 課題の実行は{ $runs }回（公称と{ $variants }個のバリアント）ですが、測定されたのは{ $measured }回です

## 課題の文面

challenge-untitled = 設計課題
challenge-title = { $title }
challenge-brief-start = シナリオ { $base } から始めます
challenge-brief-nothing-allowed = 何も変更できません：基本シナリオをそのまま判定します。
challenge-brief-allowed = 変更できるのは次の設定だけです：
challenge-brief-allow = { $field } { $range }（現在 { $now }）— { $doc }
challenge-brief-range = { $lo }～{ $hi }
challenge-brief-one-of = { $options } のいずれか
challenge-brief-formula = 自作の式
challenge-brief-formula-unit = 自作の式（単位 { $unit }）
challenge-brief-needs = 設計が満たすべき基準：
challenge-brief-need =
    { $number }. { $label }（{ $figure }）：{ $bound }{ $settled ->
        [yes] 、かつ実行終了までに整定
       *[no] {""}
    }{ $robust ->
        [yes] （公称の実行とすべてのバリアントで）
       *[no] {""}
    }
challenge-brief-at-most = { $bound }以下
challenge-brief-at-least = { $bound }以上
challenge-brief-within = ±{ $bound }以内
challenge-brief-band = 整合したフィルタの95 %区間の内側（mean_nis_low～mean_nis_high）
challenge-brief-variants-seeds = バリアント（あなたの設定に上乗せして適用し、最悪の実行で判定）：ノイズのシード{ $first }～{ $last }
challenge-brief-variants = バリアント（あなたの設定に上乗せして適用し、最悪の実行で判定）：{ $overrides }
challenge-brief-load-recovery = 負荷ステップ後の回復時間：負荷ステップ（t = { $time } s）から、|ω − ω_d| が max(ステップ時の |ω_d| の1 %, 0.5 rad/s) 以内に入って実行終了までとどまるまでの時間（ここでは ω_d = { $speed } rad/s で { $band } rad/s）。終了時にまだ外れていれば、回復していないとみなします。
challenge-brief-settled = 最終値は整定している場合にのみ有効です：実行の最後の十分の一でまだ変化している値は不合格です。
challenge-quantity = { $value } { $unit }

## 基準の限界値と、不合格の理由

challenge-bound-max = ≤ { $bound }
challenge-bound-min = ≥ { $bound }
challenge-bound-abs = |·| ≤ { $bound }
challenge-bound-band = 95 %区間の内側
challenge-run-unfinished = 実行が最後まで終わりませんでした
challenge-reason-run-failed = 実行に失敗：{ $failure }
challenge-reason-not-finite = { $cause }
challenge-reason-before-load-step = 未測定：負荷ステップの前に実行が終わります
challenge-reason-not-measured = この実行では未測定（例：2 %以内に整定しないステップ）
challenge-reason-no-band = 未測定：この実行にはNISの区間がありません
challenge-reason-above-bound = 上限を超えている
challenge-reason-below-bound = 下限を下回っている
challenge-reason-beyond-bound = 許容幅を超えている
challenge-reason-below-band = 区間を下回っている
challenge-reason-above-band = 区間を上回っている
challenge-reason-not-recovered = 実行終了までに回復せず
challenge-reason-still-changing = まだ変化中

## クラスの採点：各提出の状態（採点結果のCSVにも入る）とクラスのファイル

grade-row-ok = OK
grade-row-malformed = 不正な形式：{ $reason }
grade-row-refused = 却下：{ $reason }
grade-row-another = 別の課題
grade-row-run-failed = 実行に失敗：{ $reason }
grade-internal-error = 内部エラー
grade-line-undecoded = { $line }行目は有効な{ $encoding }ではありません
grade-line-unclosed = { $line }行目：引用符で囲まれたフィールドが、ファイルの終わりまでに閉じられていません
grade-line-fields = { $line }行目のフィールドは{ $fields }個ですが、ヘッダは{ $header }個です
grade-no-link = リンクなし
grade-challenge-refused = 課題：{ $error }
grade-file-not-text = ファイルがテキストではありません（NULバイトを含みます。表計算や文書のファイルではありませんか？）：一行に一つのリンクを書いたテキストファイルか、CSVとして保存してください
grade-file-utf16 = ファイルはバイト順マークのないUTF-16です：UTF-8で保存してください
grade-file-header-undecoded = CSVのヘッダである{ $line }行目は有効な{ $encoding }ではありません
grade-file-no-link-column = このCSV書き出しにはリンクの列がありません（列：{ $columns }）：リンクの列の見出しを 'link' にしてください
grade-file-links-everywhere = 列 { $columns } のすべてにリンクが入っています：採点する列の見出しを 'link' にしてください
grade-file-link-headers = 列 { $columns } のすべての見出しがリンクの列を示しています：一つだけにしてください

## 中断された採点の再開（imlab grade --resume）：以前の出力が却下される理由

grade-resume-not-utf8 = UTF-8のテキストではないため、このクラスの採点結果ではありません
grade-resume-header = 最初の行がこの採点のヘッダ '{ $header }' ではありません：別の課題かクラスのファイルの採点結果です
grade-resume-too-many-rows = クラスのファイルの提出数（{ $rows }件）より多くの行があります
grade-resume-row = { $row }行目がクラスのファイルの{ $line }行目（'{ $link }'）のものではありません：別のクラスのファイルの採点結果です
grade-kept-differs = { $row }行目（クラスのファイルの{ $line }行目）が、もう一度採点した結果と異なります：{ $what }。採点後に編集されたか、別のバージョンのimlabで採点されたものです
grade-kept-cell = { $column } が '{ $expected }' ではなく '{ $found }' です
grade-kept-extra = 最後の列の後に '{ $extra }' があります
grade-kept-short = { $column } 以降の列がありません
