# The core's refusals of a formula, and why a law's distance from its designed dynamics is not a
# number: said as a link is read or a run ends, with the page's first messages.
formula-at = { $at }文字目：{ $reason }
formula-not-a-number = '{ $written }' は数ではありません
formula-number-too-large = '{ $written }' は数として大きすぎます
formula-not-in-language = '{ $char }' は式に使えない文字です（使えるのは + − * / ^、括弧、名前、数）
formula-division-by-zero = ゼロで割っています
formula-nests-too-deep = ここで式の入れ子が{ $max }段を超えています
formula-ends-early = 数、名前、'(' のいずれかが来るべきところで式が終わっています
formula-never-closed = この '(' は閉じられていません
formula-expected-close = ここには ')' か演算子が必要です
formula-misplaced-operator = 数、名前、'(' のいずれかが来るべきところに '{ $op }' があります
formula-no-function = 関数 '{ $name }' はありません：使える関数は { $functions } です
formula-expected-argument-end = { $name }( ) の中に ',' か ')' が必要です
formula-arguments =
    { $name } がとる引数は{ $arity ->
       *[other] { $arity }個
    }で、{ $given }個ではありません
formula-later-name = '{ $name }' はステップ{ $step }では使えません：ステップ{ $from }の制御則で決まる名前です
formula-is-function = '{ $name }' は関数です：{ $name }( ) と書いてください
formula-true-speed = '{ $name }' は真の速度で、センサレス制御器はこれをもちません：推定値 x1h を書いてください
formula-true-flux = '{ $name }' は回転子磁束の真値で、どのドライブも測定しません：推定値 x4h か x5h を書いてください
formula-unmeasured-error = '{ $name }' は測定されない状態の推定誤差で、センサレス制御器には知りようがありません：論文はこうした項を d̃2 と d̃4 に残しており、ロバスト項（robust·h²/(4ε)·z）はそれに対して設計されています
formula-unknown-name = 不明な名前 '{ $name }'（名前の一覧を参照）
formula-too-long = 式は{ $length }文字あり、許容される{ $max }文字を超えています
formula-empty = 式が空です
formula-unopened = この ')' の前に '(' がありません
formula-expected-operator = ここには演算子が必要です（積は * で書きます）
formula-too-many-operations = 式の演算数は{ $operations }で、許容される{ $max }を超えています
formula-too-deep = 式の値の入れ子が{ $depth }段あり、許容される{ $max }段を超えています：括弧の入れ子を減らして書いてください
law-refused = law.v{ $step }：{ $error }
law-no-such-step = ステップ{ $step }：ステップは1～4です
law-none = シナリオに自作の制御則がありません：law.v1、law.v2、law.v3、law.v4 のいずれかを指定してください
law-no-own-law = このステップには自作の制御則がありません
law-not-designed-one = 制御則が設計どおりのダイナミクスを与えません
law-not-designed-some = { $laws }個の制御則のうち{ $failed }個が設計どおりのダイナミクスを与えません
law-never-runs = あなたの{ $before }は抽出した{ $draws }個の状態のどれでも有限の値を与えないため、ステップ{ $step }は一度も実行されません
law-no-share = 論文の制御則がほぼゼロになるところで、あなたの{ $output }（{ $unit }）が設計どおりのダイナミクスを与える{ $output }と異なり、その差は大きさに対する有限の割合になりません
law-differs-infinitely =
    あなたの{ $output }（{ $unit }）は、抽出した{ $draws }個の状態のうち{ $count }個で、設計どおりのダイナミクスを与える{ $output }と無限に異なります{ $reads ->
        [none] （制御則はどの信号も読んでいません）
       *[some] （例：{ $names } のとき）
    }
law-not-finite =
    あなたの{ $output }（{ $unit }）は、抽出した{ $draws }個の状態のうち{ $count }個で有限の数になりません：{ $value } を与えます{ $reads ->
        [none] （制御則はどの信号も読んでいません）
       *[some] （{ $names } のとき）
    }
law-named-value = { $name } = { $value }
law-paper-zero = 論文の制御則は実行全体を通じてゼロのままでしたが、あなたの制御則はそうではありませんでした
